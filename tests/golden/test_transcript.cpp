// The transcript format itself: every kind of line reads back as it was written.
#include <catch2/catch.hpp>

#include "transcript.hpp"

using namespace imess::golden;

TEST_CASE("transcript lines read and write back unchanged") {
  const std::string text =
      "# a comment\n\n@ config/sim-servo-card.json\n< CurrCor 1.000 2.000 3.000\n> Hello golden\n"
      "> \n+2 127.0.0.2\n2> Status\n2>> Get\n2< Ok Status\n= 250 ms\n~ 12 ms\n-2\n> A\\x01B\\\\\n";
  const auto entries = parse_transcript(text, "t");
  REQUIRE(entries.size() == 14);
  CHECK(entries[2].kind == EntryKind::Config);
  CHECK(entries[5].kind == EntryKind::Send);
  CHECK(entries[5].text.empty());
  CHECK(entries[6].kind == EntryKind::Connect);
  CHECK(entries[6].client == 2);
  CHECK(entries[6].text == "127.0.0.2");
  CHECK(!entries[7].joined);
  CHECK(entries[8].joined);
  CHECK(entries[8].text == "Get");
  CHECK(entries[10].ms == 250);
  CHECK(entries[11].kind == EntryKind::Time);
  CHECK(entries[13].text == std::string("A\x01" "B\\"));
  CHECK(format_transcript(entries) == text);
}

TEST_CASE("a line that is not in the format is an error naming it") {
  CHECK_THROWS_WITH(parse_transcript("@ x\nGoTo 1 2 3\n", "f.txt"), Catch::Contains("f.txt:2"));
  CHECK_THROWS_WITH(parse_transcript("= 5 s\n", "f.txt"), Catch::Contains("ms"));
  CHECK_THROWS_WITH(parse_transcript("> a\\qb\n", "f.txt"), Catch::Contains("backslash"));
}
