// What the I++ DME properties (test_ippdme_properties.cpp) found messd doing against
// IPPDME.md, each alone in a minimal script on the default simulated CMM. A case tagged
// [!shouldfail] passes while messd still does it and fails once it is fixed: then drop the
// tag, and the property's tolerance named in the case.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "golden_harness.hpp"

namespace imess::golden {
namespace {

std::vector<std::string> session_lines(const std::string& script) {
  std::vector<std::string> lines;
  for (const auto& e : replay(parse_transcript(script, "finding"), "finding"))
    if (e.kind == EntryKind::Receive && e.client == 2) lines.push_back(e.text);
  return lines;
}

long index_of(const std::vector<std::string>& lines, const std::string& line) {
  const auto it = std::find(lines.begin(), lines.end(), line);
  return it == lines.end() ? -1 : static_cast<long>(it - lines.begin());
}

// IPPDME.md §3: completions come back in the order the commands were started; §4: on an
// error of severity 2 or more the server aborts all pending transactions. A garbled line
// while a GoTo runs (so do a reused tag, or a fast command's error) aborts only what waits
// behind the GoTo: its Get gets 0006 and `%` first, the GoTo goes on in the error state and
// completes 4 s later without an error. Tolerated by the properties as
// kQueueAbortedAheadOfItsMove (ippdme_property_rules.cpp).
TEST_CASE("I++ DME finding: an error while a GoTo runs completes the queue behind it first", "[!shouldfail]") {
  const auto lines = session_lines(
      "@ config/sim-servo-card.json\n"
      "+2 ipp\n"
      "2> 00001 StartSession()\n"
      "2> 00002 GoTo(Z(300))\n"
      "2>> 00003 Get(Z())\n"
      "= 100 ms\n"
      "2> 00004 Get(Z()\n"
      "= 4000 ms\n");
  const long go_to = index_of(lines, "00002 %"), get = index_of(lines, "00003 %");
  REQUIRE(go_to >= 0);
  REQUIRE(get >= 0);
  CHECK(go_to < get);
}

}  // namespace
}  // namespace imess::golden
