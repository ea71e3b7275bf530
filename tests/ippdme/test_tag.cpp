// Tags: the two kinds, the reserved ones, their text, and the tracker of open tags.
#include <catch2/catch.hpp>

#include "imess/ippdme/tag.hpp"

using namespace imess::ippdme;

TEST_CASE("ippdme tags: command tags 00001..99999, event tags E0001..E9999") {
  CHECK(parse_client_tag("00001") == Tag{TagKind::Command, 1});
  CHECK(parse_client_tag("99999") == Tag{TagKind::Command, 99999});
  CHECK(parse_client_tag("E0001") == Tag{TagKind::Event, 1});
  CHECK(parse_client_tag("E9999") == Tag{TagKind::Event, 9999});
  for (const char* bad : {"00000", "E0000", "0001", "000001", "E001", "E00001", "e0001", "0000a", " 0001",
                          "+0001", "-0001", "F0001", "EE001", "", "E"}) {
    INFO(bad);
    CHECK_FALSE(parse_client_tag(bad));
  }
  CHECK(parse_event_tag("E0005") == Tag{TagKind::Event, 5});
  CHECK_FALSE(parse_event_tag("00005"));
  CHECK_FALSE(parse_event_tag("E0000"));
}

TEST_CASE("ippdme tags are written in five characters, E0000 for the server") {
  CHECK(tag_text({TagKind::Command, 1}) == "00001");
  CHECK(tag_text({TagKind::Command, 99999}) == "99999");
  CHECK(tag_text({TagKind::Event, 42}) == "E0042");
  CHECK(tag_text(kServerTag) == "E0000");
  CHECK(tag_text({TagKind::Event, 10001}) == "E0001");  // out of range: still five characters
}

TEST_CASE("ippdme tag tracker: a tag is refused while its transaction is open") {
  TagTracker t;
  const Tag a{TagKind::Command, 7}, e{TagKind::Event, 7};
  CHECK(t.try_open(a));
  CHECK(t.is_open(a));
  CHECK_FALSE(t.is_open(e));  // the kinds are separate
  CHECK_FALSE(t.try_open(a));
  CHECK(t.try_open(e));
  CHECK(t.open_count() == 2);
  t.close(a);
  CHECK_FALSE(t.is_open(a));
  CHECK(t.try_open(a));  // reusable after its %
  CHECK_FALSE(t.try_open(kServerTag));
  CHECK_FALSE(t.try_open({TagKind::Command, 0}));
  CHECK_FALSE(t.try_open({TagKind::Command, 100000}));
  t.close({TagKind::Event, 50000});  // ignored
  t.clear();
  CHECK(t.open_count() == 0);
}
