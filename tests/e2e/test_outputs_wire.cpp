// Outputs over TCP against a real messd. On the simulated servo card: DirectCMM's STARTUP and
// SHUTDOWN (BRIEF §2) — the probe's power edges are not hits (Warn HitIgnored), a Probe with
// the probe off fails ProbeOff, switched on again the probe measures. On the MRM arm: the
// gripper closes between two moves, after the first has arrived, and Outputs shows it.
#include <catch2/catch.hpp>

#include <optional>
#include <unistd.h>

#include "daemon_process.hpp"
#include "private_config.hpp"

using namespace imess::test;

namespace {
int count_prefix(const LineClient& c, const std::string& prefix) {
  int n = 0;
  for (const auto& l : c.seen()) n += l.rfind(prefix, 0) == 0;
  return n;
}
bool seen(const LineClient& c, const std::string& line) {
  for (const auto& l : c.seen())
    if (l == line) return true;
  return false;
}
}  // namespace

TEST_CASE("probe power on the servo card: power edges are not hits, a Probe with the probe off fails ProbeOff") {
  DaemonProcess messd({"--config", std::string(IMESS_SOURCE_DIR) + "/tests/e2e/fast-cmm.json"});
  LineClient c(messd.port());
  // On at start; armed 100 ms after messd started the card.
  std::optional<std::string> outputs;
  for (int i = 0; i < 50 && outputs != std::string("Ok Outputs probe on ProbeArmed yes"); ++i) {
    outputs = c.request("Outputs");
    REQUIRE(outputs);
    CHECK(outputs->rfind("Ok Outputs probe on ProbeArmed ", 0) == 0);
    usleep(20'000);
  }
  REQUIRE(outputs == std::string("Ok Outputs probe on ProbeArmed yes"));
  // SHUTDOWN: the power-off edge is ignored; a Probe into the cube top fails before it moves.
  REQUIRE(c.request("SetOut 1 probe off") == std::string("Ok SetOut"));
  REQUIRE(c.until([](const std::string& l) { return l == "Done 1"; }, 20));
  CHECK(seen(c, "Warn HitIgnored probe edge while the probe is switched off; no point taken"));
  REQUIRE(c.request("Outputs") == std::string("Ok Outputs probe off ProbeArmed no"));
  c.send("Probe 2 Z81");  // the cube top at z = 80 below the start (430, 330, 100): the ball centre touches at 82
  REQUIRE(c.until([](const std::string& l) { return l.rfind("Failed 2", 0) == 0; }, 20));
  CHECK(seen(c, "Failed 2 ProbeOff the probe is switched off: SetOut <id> <its output> on first"));
  CHECK(count_prefix(c, "Hit ") == 0);
  REQUIRE(c.until([](const std::string& l) { return l == "State idle"; }, 10));  // braked: it stands
  // STARTUP, then the same Probe measures the top.
  c.send("SetOut 3 probe on\nProbe 4 Z81");
  REQUIRE(c.until([](const std::string& l) { return l == "Done 4" || l.rfind("Failed 4", 0) == 0; }, 30));
  INFO(c.raw());
  CHECK(seen(c, "Done 3"));
  CHECK(seen(c, "Done 4"));
  CHECK(count_prefix(c, "Warn HitIgnored") == 2);  // the off and the on edge
  CHECK(seen(c, "Warn HitIgnored edge within the probe's arming time; no point taken"));
  REQUIRE(count_prefix(c, "Hit ") == 1);
  for (const auto& l : c.seen())
    if (l.rfind("Hit ", 0) == 0) {
      std::istringstream in(l.substr(4));
      double seq, id, x, y, z;
      in >> seq >> id >> x >> y >> z;
      CHECK(id == 4);
      CHECK(z == Approx(80).margin(0.005));
    }
  REQUIRE(c.request("Outputs") == std::string("Ok Outputs probe on ProbeArmed yes"));
  // Names the machine lacks, and words that are no state, are refused with what is accepted.
  CHECK(c.request("SetOut 5 gripper on") == std::string("Err 105 SetOut 5: no output 'gripper'; this machine has the outputs probe"));
  CHECK(c.request("SetOut 5 probe maybe")->rfind("Err 105 SetOut switches an output on or off, got 'maybe'", 0) == 0);
  c.send("Quit");
}

TEST_CASE("the MRM arm's gripper: SetOut between two moves switches after the first arrived and holds its settle time") {
  const std::string config = private_port_config(std::string(IMESS_SOURCE_DIR) + "/config/sim-mrm-arm.json");
  DaemonProcess messd({"--config", config});
  LineClient c(messd.port());
  REQUIRE(c.request("Outputs") == std::string("Ok Outputs gripper off ProbeArmed yes"));
  c.send("MoveTo 1 X220 F40\nSetOut 2 gripper on\nMoveTo 3 X200 F40");
  REQUIRE(c.until([](const std::string& l) { return l == "Done 3" || l.rfind("Failed", 0) == 0; }, 30));
  INFO(c.raw());
  std::vector<std::string> order;
  for (const auto& l : c.seen())
    if (l == "Done 1" || l == "Done 2" || l == "Done 3") order.push_back(l);
  CHECK(order == std::vector<std::string>{"Done 1", "Done 2", "Done 3"});
  REQUIRE(c.request("Outputs") == std::string("Ok Outputs gripper on ProbeArmed yes"));
  c.send("SetOut 4 gripper off");
  REQUIRE(c.until([](const std::string& l) { return l == "Done 4"; }, 10));
  REQUIRE(c.request("Outputs") == std::string("Ok Outputs gripper off ProbeArmed yes"));
  c.send("Quit");
  std::filesystem::remove(config);
}
