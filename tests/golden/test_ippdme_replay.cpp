// The I++ DME conformance replay (issue 25, section 2): the command files written here
// (tests/golden/ippdme-conformance/*.txt, README.md there) run against messd's simulated machine;
// each keeps the framing rules and its own expectations, and together they send every method
// the library declares and ask for every error number the server sends.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

#include "golden_files.hpp"
#include "golden_harness.hpp"
#include "imess/ippdme/command_spec.hpp"
#include "imess/ippdme/error_code.hpp"
#include "ippdme_conformance.hpp"

namespace imess::golden {
namespace {

std::filesystem::path conformance_dir() { return golden_dir() / "ippdme-conformance"; }

std::vector<std::filesystem::path> command_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& f : std::filesystem::directory_iterator(conformance_dir()))
    if (f.path().extension() == ".txt") files.push_back(f.path());
  std::sort(files.begin(), files.end());
  return files;
}

ConformanceReport run(const std::filesystem::path& path) {
  const std::string name = path.filename().string();
  const auto script = parse_transcript(read_text(path), name);
  return check_conformance(script, replay(script, name));
}

std::string tail(const std::vector<std::string>& lines) {
  std::string out;
  for (std::size_t i = lines.size() > 40 ? lines.size() - 40 : 0; i < lines.size(); ++i) out += lines[i] + "\n";
  return out;
}

// Error numbers no command file asks for, and why (docs/ippdme.md, "Not supported").
const std::set<int> kNeverSent{
    0,     // Buffer full: the server's flow control is the delayed Ack
    500,   // Emergency stop: a fault fails the running command with 1000 (E0000 errors not sent yet)
    503,   // Controller communications failure: the controller is messd itself
    1003,  // No touch: a search without contact is 1006 Surface not found
    1005,  // Error during home: the simulated machines home without fail
    1008,  // Target out of machine volume: a target beyond the travel is 2500
    1009,  // Air pressure out of range: no air bearings watched
    2504,  // Collision: a touch where none is expected is 1001 Illegal touch
};

}  // namespace

TEST_CASE("I++ DME conformance replay: every command file keeps the framing rules and its expectations") {
  const auto files = command_files();
  REQUIRE(files.size() >= 8);
  for (const auto& path : files) {
    const auto report = run(path);
    INFO(path.filename().string() << " received (last lines):\n" << tail(report.received));
    for (const auto& f : report.failures) {
      INFO(path.filename().string() << ": " << f);
      CHECK(false);
    }
    CHECK(report.failures.empty());
    CHECK(!report.received.empty());
  }
}

TEST_CASE("I++ DME conformance replay: the files send every method and ask for every error number the server sends") {
  std::set<std::string> methods;
  std::set<int> errors;
  for (const auto& path : command_files()) {
    const auto report = run(path);
    methods.insert(report.methods.begin(), report.methods.end());
    errors.insert(report.expected_errors.begin(), report.expected_errors.end());
  }
  for (const auto& spec : ippdme::command_table()) {
    INFO(spec.name);
    CHECK(methods.count(std::string(spec.name)) == 1);
  }
  std::set<int> severities;
  for (const auto& e : ippdme::error_table()) {
    const int n = ippdme::number_of(e.code);
    INFO(n);
    CHECK(errors.count(n) == (kNeverSent.count(n) ? 0u : 1u));
    if (errors.count(n)) severities.insert(ippdme::severity_number(e.severity));
  }
  CHECK(severities == std::set<int>{1, 2, 3});  // warning, error, operator error (0 and 9: never sent)
}

// The two measuring programs run to the end: every command completes, none refused by the error
// state, EndSession closes them.
TEST_CASE("I++ DME conformance replay: the measuring programs run to the end") {
  int programs = 0;
  for (const auto& path : command_files()) {
    if (path.filename().string().rfind("program-", 0) != 0) continue;
    ++programs;
    const auto report = run(path);
    INFO(path.filename().string() << "\n" << tail(report.received));
    CHECK(report.failures.empty());
    REQUIRE(report.received.size() >= 2);
    const auto& last = report.received.back();
    CHECK(last.size() == 7);
    CHECK(last.substr(5) == " %");
    CHECK(report.methods.count("EndSession") == 1);
    for (const auto& l : report.received) CHECK(l.find("0514") == std::string::npos);
  }
  CHECK(programs == 2);
}

// The checker itself: each rule it keeps is broken once in a made-up exchange and must be seen.
TEST_CASE("I++ DME conformance replay: the checker sees each broken rule") {
  auto failures = [](std::vector<std::string> sent_then_received, const std::string& expectation = "") {
    std::vector<Entry> script, replayed;
    for (const auto& s : sent_then_received) {
      const bool send = s.rfind("> ", 0) == 0;
      replayed.push_back({send ? EntryKind::Send : EntryKind::Receive, 2, s.substr(2)});
    }
    if (!expectation.empty()) script.push_back({EntryKind::Comment, 1, "#? " + expectation});
    return check_conformance(script, replayed).failures.size();
  };
  const std::vector<std::string> good{"> 00001 Get(X())", "< 00001 &", "< 00001 # X(1.0000)", "< 00001 %"};
  CHECK(failures(good) == 0);
  CHECK(failures(good, "00001 ok") == 0);
  CHECK(failures(good, "00001 data X(1.0000)") == 0);
  CHECK(failures(good, "00001 near X(1.01)") == 0);
  CHECK(failures(good, "00001 near X(1.1)") == 1);
  CHECK(failures(good, "00001 error 0502") == 1);
  CHECK(failures(good, "00001 lines 2") == 1);
  CHECK(failures(good, "00001 none") == 1);
  CHECK(failures(good, "00001 frobnicate") == 1);
  CHECK(failures({"> 00001 Get(X())", "< 00001 # X(1.0000)", "< 00001 &", "< 00001 %"}) >= 1);   // no Ack first
  CHECK(failures({"> 00001 Get(X())", "< 00001 &"}) >= 1);                                       // never completed
  CHECK(failures({"> 00001 Get(X())", "< 00002 &"}) >= 1);                                       // a tag not sent
  CHECK(failures({"> 00001 Home()", "> 00002 Home()", "< 00001 &", "< 00002 &", "< 00002 %", "< 00001 %"}) == 1);  // order
  CHECK(failures({"> 00001 Home()", "< 00001 &", "< 00001 %", "< 00001 # X(1)"}) == 1);           // after its %
  CHECK(failures({"> 00001 Home()", "< 00001 &", "< 00001 ! Error(2, 0502, Home, \"Incorrect arguments\")", "< 00001 %"}) == 1);  // severity
  CHECK(failures({"> 00001 Home()", "< 00001 &", "< 00001 ! Error(2, 0514, Home, \"Use ClearAllErrors to continue\")", "< 00001 %"}) == 1);
  CHECK(failures({"> 00001 Home()", "< 00001 &", "< 00001 ! Error(2, 0514, Home, \"Use ClearAllErrors to continue\")", "< 00001 %"},
                 "00001 error 0514") == 0);
  CHECK(failures({"> 00001 Home()", "< 00001 & [no CR]", "< 00001 %"}) >= 1);
  CHECK(failures({"> 012345 Home()", "< E0000 ! Error(2, 0001, \"012345 Home()\", \"Illegal tag\")"}, "E0000 error 0001") == 0);
  CHECK(failures({"> 012345 Home()", "< E0000 &"}) == 1);
  CHECK(near_payload("X(460), Y(350)", "X(460.0049), Y(349.9961)", 0.05));
  CHECK_FALSE(near_payload("X(460), Y(350)", "X(460.0049), Z(349.9961)", 0.05));
}

}  // namespace imess::golden
