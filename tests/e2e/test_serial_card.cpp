// The servo card on a real serial line (issue 27): messd's "servo-card" backend against
// messcard on a pseudo-terminal, both real programs in real time — motion over the stream,
// the card killed and brought back, the cable pulled, a stall, damaged bytes counted and the
// host frames they hit sent again or, when the path cannot survive them, a controlled stop
// with Fault LinkErrors.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>
#include <tuple>
#include <utility>

#include "daemon_process.hpp"
#include "messcard_process.hpp"

using namespace imess::test;

namespace {

const std::string kCardConfig = std::string(IMESS_SOURCE_DIR) + "/config/servo-card.json";

// messd on the card's pseudo-terminal, with SCHED_FIFO where permitted (as messcard asks for
// it): two programs in real time on a loaded 2-core host stall each other otherwise.
DaemonProcess messd_on(const MesscardProcess& card) {
  return DaemonProcess({"--config", kCardConfig, "--device", card.tty()}, DaemonProcess::Scheduling::RealtimeIfPermitted);
}

// The number after `name` in a reply line (NaN when absent).
double card_field(const std::string& line, const std::string& name, int index = 0) {
  std::istringstream in(line);
  std::string w;
  while (in >> w)
    if (w == name) {
      double v = NAN;
      for (int i = 0; i <= index; ++i) in >> v;
      return v;
    }
  return NAN;
}

std::string card_status(LineClient& c) { return c.request("Status").value_or(""); }
bool card_state_is(LineClient& c, const std::string& state) {
  return card_status(c).find("State " + state + " ") != std::string::npos;
}
double card_link_errors(LineClient& c) { return card_field(c.request("Stats").value_or(""), "LinkErrors"); }
// Waits (polling Status) until State is `state`; false after timeout_s.
bool card_wait_state(LineClient& c, const std::string& state, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (card_state_is(c, state)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}
// Reset until the machine leaves Fault (a re-boot takes a few set-up exchanges).
bool card_reset(LineClient& c, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    c.request("Reset");
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (!card_state_is(c, "fault")) return true;
  }
  return false;
}
bool card_goto(LineClient& c, double x, double y, double z) {
  std::ostringstream cmd;
  cmd << "GoTo " << x << " " << y << " " << z << " 100";
  // Right after a Reset that re-boots the card the driver refuses motion until the card is
  // back (a few set-up exchanges, tens of ms): try again for a while.
  std::optional<std::string> reply;
  for (int i = 0; i < 30 && (reply = c.request(cmd.str())) != std::optional<std::string>("Ok GoTo"); ++i) {
    std::printf("servo-card: %s -> %s (re-booting?)\n", cmd.str().c_str(), reply.value_or("no reply").c_str());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (reply != std::optional<std::string>("Ok GoTo")) return false;
  const bool idle = card_wait_state(c, "idle", 10);
  const std::string s = card_status(c);
  if (!idle) {
    std::printf("servo-card: %s did not end idle: %s\n", cmd.str().c_str(), s.c_str());
    for (const auto& l : c.seen())
      if (l.rfind("Fault ", 0) == 0) std::printf("servo-card: it saw %s\n", l.c_str());
  }
  return idle && std::abs(card_field(s, "Pos", 0) - x) < 0.01 && std::abs(card_field(s, "Pos", 1) - y) < 0.01 &&
         std::abs(card_field(s, "Pos", 2) - z) < 0.01;
}
using CardClock = std::chrono::steady_clock;
double card_ms_since(CardClock::time_point t) { return std::chrono::duration<double, std::milli>(CardClock::now() - t).count(); }

}  // namespace

TEST_CASE("servo-card: messd streams to messcard over a pseudo-terminal — GoTo and a queued path arrive, no link error") {
  MesscardProcess card;
  DaemonProcess messd = messd_on(card);
  LineClient c(messd.port());
  CHECK(card_state_is(c, "free"));
  CHECK(card_goto(c, 450, 340, 120));
  REQUIRE(c.request("MoveTo 1 X470 Y350 F80") == std::optional<std::string>("Ok MoveTo"));
  REQUIRE(c.request("MoveTo 2 X460 Y360 Z110 F80") == std::optional<std::string>("Ok MoveTo"));
  CHECK(c.until_prefix("Done 2", 10));
  CHECK(card_wait_state(c, "idle", 5));
  const std::string s = card_status(c);
  CHECK(std::abs(card_field(s, "Pos", 0) - 460) < 0.01);
  CHECK(std::abs(card_field(s, "Pos", 2) - 110) < 0.01);
  CHECK(card_link_errors(c) == 0);
}

TEST_CASE("servo-card: the card killed is Fault CommLost within 50 ms — started again, Reset re-boots it and it moves") {
  MesscardProcess card;
  DaemonProcess messd = messd_on(card);
  LineClient c(messd.port());
  REQUIRE(card_goto(c, 440, 330, 110));
  const auto killed = CardClock::now();
  card.stop(SIGKILL);
  REQUIRE(c.until_prefix("Fault CommLost", 2));
  const double latency = card_ms_since(killed);
  std::printf("servo-card: messcard killed -> Fault CommLost after %.1f ms\n", latency);
  CHECK(latency < 50);
  // Not back yet: Reset finds no card and the fault stays.
  c.request("Reset");
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  CHECK(card_state_is(c, "fault"));
  // The card comes back on the same path (a new pseudo-terminal behind the link).
  MesscardProcess again({}, "", std::filesystem::path(card.tty()).parent_path().string());
  REQUIRE(card_reset(c, 10));
  CHECK(card_goto(c, 445, 335, 105));  // without restarting messd
  CHECK(messd.running());
}

TEST_CASE("servo-card: the cable pulled during a path: CommLost within 50 ms, messcard shows its watchdog braked") {
  MesscardProcess card;
  DaemonProcess messd = messd_on(card);
  LineClient c(messd.port());
  REQUIRE(card_goto(c, 300, 300, 100));
  REQUIRE(c.request("MoveTo 1 X600 F100") == std::optional<std::string>("Ok MoveTo"));
  REQUIRE(c.until_prefix("State move", 2));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto pulled = CardClock::now();
  card.signal(SIGTERM);
  REQUIRE(c.until_prefix("Fault CommLost", 2));
  const double latency = card_ms_since(pulled);
  std::printf("servo-card: cable pulled (SIGTERM) -> Fault CommLost after %.1f ms\n", latency);
  CHECK(latency < 50);
  CHECK(card.until("watchdog: the setpoints stopped coming; the axes braked", 5));
  CHECK(card.until("card at rest", 5));
  card.stop(SIGTERM);
}

TEST_CASE("servo-card: a stall of the card is CommLost — once it answers again Reset resumes the stream") {
  MesscardProcess card({"--stall-ms", "150", "--stall-at-ms", "600"});
  DaemonProcess messd = messd_on(card);
  LineClient c(messd.port());
  REQUIRE(c.until_prefix("Fault CommLost", 5));
  CHECK(card.until("answering again", 5));
  REQUIRE(card_reset(c, 5));
  CHECK(card_goto(c, 440, 340, 100));
}

TEST_CASE("servo-card: damaged status frames at rest are counted in Stats LinkErrors and survived") {
  MesscardProcess card({"--corrupt", "0.001", "--seed", "7"});
  DaemonProcess messd = messd_on(card);
  LineClient c(messd.port());
  const auto deadline = CardClock::now() + std::chrono::seconds(10);
  double errors = 0;
  while (CardClock::now() < deadline && (errors = card_link_errors(c)) < 3)
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  std::printf("servo-card: --corrupt 0.001 at rest: LinkErrors %.0f\n", errors);
  CHECK(errors >= 3);
  CHECK(card_state_is(c, "free"));  // no fault: each damaged frame is dropped, the next one taken
}

// Runs MoveTo 1 from (300, 300, 100) to (700, 500) at 100 mm/s; the first line of Fault or
// Done 1, and where the machine came to rest, how far off the planned line.
struct PathEnd {
  std::string end;
  double x = NAN, y = NAN, off_line = NAN;
};
// `started` runs once the path has begun.
template <class Started>
PathEnd run_planned_line(LineClient& c, Started&& started) {
  PathEnd r;
  REQUIRE(card_goto(c, 300, 300, 100));
  REQUIRE(c.request("MoveTo 1 X700 Y500 F100") == std::optional<std::string>("Ok MoveTo"));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  started();
  auto end = c.until([](const std::string& l) { return l.rfind("Fault ", 0) == 0 || l.rfind("Done 1", 0) == 0; }, 15);
  REQUIRE(end);
  r.end = *end;
  std::string s, last;
  for (int i = 0; i < 50; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    s = card_status(c);
    if (s == last) break;
    last = s;
  }
  CHECK(s == last);
  r.x = card_field(s, "Pos", 0);
  r.y = card_field(s, "Pos", 1);
  r.off_line = std::abs((r.x - 300) * 200 - (r.y - 300) * 400) / std::hypot(400.0, 200.0);
  return r;
}

TEST_CASE("servo-card: damaged bytes on a path: the host frames hit are sent again and the path ends Done", "[alone]") {
  // From the first byte on: set-up retries what is hit, the GoTo and the path are sent again.
  MesscardProcess card({"--corrupt", "0.0003", "--seed", "5"});
  DaemonProcess messd = messd_on(card);
  LineClient c(messd.port());
  const double before = card_link_errors(c);
  const PathEnd r = run_planned_line(c, [] {});
  const double errors = card_link_errors(c) - before;
  std::printf("servo-card: --corrupt 0.0003 on a 447 mm path: %s; LinkErrors +%.0f; at X %.3f Y %.3f\n", r.end.c_str(),
              errors, r.x, r.y);
  CHECK(r.end.rfind("Done 1", 0) == 0);
  CHECK(errors >= 1);  // damaged frames were met, counted, and survived
  CHECK(std::abs(r.x - 700) < 0.01);
  CHECK(std::abs(r.y - 500) < 0.01);
  CHECK(card.until("a damaged frame from the host", 2));
}

TEST_CASE("servo-card: a byte error rate the path cannot survive stops it with Fault LinkErrors, on the planned line", "[alone]") {
  // Set-up and the GoTo clean; half a second into the path every 20th byte is hit, both ways.
  MesscardProcess card({"--corrupt", "0.05", "--faults-at-ms", "3600000", "--seed", "3"});
  DaemonProcess messd = messd_on(card);
  LineClient c(messd.port());
  const PathEnd r = run_planned_line(c, [&] { card.signal(SIGUSR2); });
  std::printf("servo-card: --corrupt 0.05 on a path: %s; stopped at X %.3f Y %.3f, %.4f mm off the planned line; "
              "LinkErrors %.0f\n", r.end.c_str(), r.x, r.y, r.off_line, card_link_errors(c));
  CHECK(r.end.rfind("Fault LinkErrors", 0) == 0);
  // The machine comes to rest on the planned line from (300, 300) to (700, 500).
  CHECK(r.off_line < 0.2);
  CHECK(r.x >= 300 - 0.2);
  CHECK(r.x <= 700 + 0.2);
  CHECK(card.until("a damaged frame from the host", 2));
}

TEST_CASE("messcard: bad options and configurations are refused with exit 2 saying what is accepted") {
  const auto run = [](const std::string& args) {
    const std::string cmd = std::string(IMESS_BIN_DIR) + "/messcard " + args + " 2>&1";
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    char buf[512];
    while (p && fgets(buf, sizeof buf, p)) out += buf;
    const int st = p ? pclose(p) : -1;
    return std::make_pair(WIFEXITED(st) ? WEXITSTATUS(st) : -1, out);
  };
  auto [status, out] = run("--config " + kCardConfig);
  CHECK(status == 2);
  CHECK_THAT(out, Catch::Contains("--pty PATH") && Catch::Contains("--device TTY"));
  std::tie(status, out) = run("--pty /tmp/x --config " + kCardConfig + " --corrupt 2");
  CHECK(status == 2);
  CHECK_THAT(out, Catch::Contains("--corrupt takes a number from 0"));
  std::tie(status, out) = run("--pty /tmp/x --config /nonexistent.json");
  CHECK(status == 2);
  CHECK_THAT(out, Catch::Contains("/nonexistent.json"));
}

TEST_CASE("messcard: every shipped sim-servo-card configuration is a card messd streams to") {
  int configs = 0;
  for (const auto& f : std::filesystem::directory_iterator(std::string(IMESS_SOURCE_DIR) + "/config")) {
    const std::string name = f.path().filename().string();
    if (name.rfind("sim-servo-card", 0) != 0 || f.path().extension() != ".json") continue;
    INFO(name);
    ++configs;
    MesscardProcess card({}, f.path().string());
    DaemonProcess messd = messd_on(card);
    LineClient c(messd.port());
    const std::string s = card_status(c);
    CHECK(s.find("State free ") != std::string::npos);
    // The machine is the file's: the simulated CMM's start position.
    CHECK(std::abs(card_field(s, "Pos", 0) - 430) < 0.01);
    CHECK(card_link_errors(c) == 0);
  }
  CHECK(configs >= 3);
}
