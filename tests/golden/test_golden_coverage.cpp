// What the golden transcripts must cover: every shipped configuration, and every error code
// of docs/protocol.md's table — except the few that no virtual-time replay can produce,
// each listed below with the test that covers it instead.
#include <catch2/catch.hpp>

#include <map>
#include <set>

#include "shipped_config.hpp"
#include "doc_table.hpp"
#include "golden_files.hpp"
#include "imess/ippdme/error_code.hpp"
#include "transcript.hpp"

using namespace imess::golden;

namespace {

std::vector<Entry> entries_of(const std::filesystem::path& p) {
  return parse_transcript(read_text(p), p.filename().string());
}

// Codes no transcript can show: why, and which test covers them.
const std::map<std::string, std::string> kNotInTranscripts = {
    {"211", "Dropped: the silence timer runs on the wall clock, idle_drop_s is at least 1 s; "
            "test_net_e2e \"a silent client holding control is dropped with Err 211 and the machine stops\""},
    {"500", "Internal: needs a lost motion-loop answer (a full event ring) and the 2 s wall-clock reply "
            "timeout; test_net \"a reply slot that is never answered becomes Err 500 after the timeout and later "
            "replies flow\""},
};

}  // namespace

TEST_CASE("every shipped configuration has a golden transcript") {
  std::set<std::string> used;
  for (const auto& f : golden_files())
    for (const auto& e : entries_of(f))
      if (e.kind == EntryKind::Config) used.insert(e.text);
  int shipped = 0;
  for (const auto& f : std::filesystem::directory_iterator(std::filesystem::path(IMESS_SOURCE_DIR) / "config")) {
    if (f.path().extension() != ".json" || !imess::test::simulated_config(f.path())) continue;  // real hardware: no replay
    ++shipped;
    const std::string name = "config/" + f.path().filename().string();
    INFO(name << " is not the '@' configuration of any tests/golden/*.txt");
    CHECK(used.count(name) == 1);
  }
  CHECK(shipped >= 5);
}

TEST_CASE("every error code of docs/protocol.md is answered in a golden transcript") {
  const auto codes = imess::testing::doc_table(imess::testing::read_source_file("docs/protocol.md"), "## Error codes");
  REQUIRE(codes.size() >= 20);
  std::set<std::string> seen;
  for (const auto& f : golden_files())
    for (const auto& e : entries_of(f))
      if (e.kind == EntryKind::Receive && e.text.rfind("Err ", 0) == 0) seen.insert(e.text.substr(4, e.text.find(' ', 4) - 4));
  for (const auto& [code, cells] : codes) {
    const bool excluded = kNotInTranscripts.count(code) == 1;
    INFO("Err " << code << " (" << cells.at(0) << ")");
    if (excluded)
      CHECK(seen.count(code) == 0);  // once a transcript shows it, the exclusion goes
    else
      CHECK(seen.count(code) == 1);
  }
  for (const auto& [code, why] : kNotInTranscripts) {
    INFO("excluded code " << code << " is not in the table");
    CHECK(codes.count(code) == 1);
  }
}

namespace {
// I++ DME error numbers no transcript shows, and why; every other number of the library's
// table must appear in a tests/golden/ippdme-*.txt `!` line.
const std::map<int, std::string> kIppNotInTranscripts = {
    {0, "Buffer full: the server delays its Ack instead (it stops reading beyond 64 waiting commands)"},
    {500, "Emergency stop: not sent on its own yet (a fault fails the running command with 1000)"},
    {503, "Controller communications failure: a fault fails the running command with 1000"},
    {1000, "Machine in error state: needs a fault of the backend during a move, which the replayed simulators do not make on demand (tests/e2e cover faults on MESSD)"},
    {1003, "No touch: a probe cycle's Done always follows its touch; the search's end without one is 1006"},
    {1005, "Error during home: a failed reference search, which the simulators do not make on demand"},
    {1008, "Target position out of machine volume: the server answers a target out of travel with 2500"},
    {1009, "Air pressure out of range: no air on these machines"},
    {2000, "Tool not calibrated: a probe cycle with the probe's power off; the session holds control, so no MESSD client can switch it off"},
    {2504, "Collision: a touch while moving is 1001"},
};
}  // namespace

TEST_CASE("every I++ DME error number is answered in a golden transcript, or its absence is explained") {
  std::set<int> seen;
  for (const auto& f : golden_files()) {
    if (f.filename().string().rfind("ippdme-", 0) != 0) continue;
    for (const auto& e : entries_of(f)) {
      const auto at = e.text.find(" ! Error(");
      if (e.kind != EntryKind::Receive || at == std::string::npos) continue;
      const auto comma = e.text.find(", ", at);
      seen.insert(std::stoi(e.text.substr(comma + 2, 4)));
    }
  }
  for (const auto& info : imess::ippdme::error_table()) {
    const int number = imess::ippdme::number_of(info.code);
    INFO("I++ DME error " << number << " (" << info.text << ")");
    if (kIppNotInTranscripts.count(number))
      CHECK(seen.count(number) == 0);  // once a transcript shows it, the exclusion goes
    else
      CHECK(seen.count(number) == 1);
  }
}
