// Dead-man against a real messd: when the client in control closes, resets or falls silent
// under Watch, the motion it started stops.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "net_fixture.hpp"

using namespace imess::test;
using Clock = std::chrono::steady_clock;

namespace {
double x_of(LineClient& c) {
  auto s = c.request("Status");
  REQUIRE(s);
  auto at = s->find(" Pos ");
  REQUIRE(at != std::string::npos);
  return std::stod(s->substr(at + 5));
}

// The machine stands: after braking (State idle comes as the stop begins), two readings
// 300 ms apart agree.
void require_standing(LineClient& c) {
  std::this_thread::sleep_for(std::chrono::milliseconds(150));
  double x1 = x_of(c);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  CHECK(x_of(c) == Approx(x1).margin(0.0005));
}

// The owner jogs +X at 20 mm/s (it would run for about 28 s to the travel end).
void start_jog(LineClient& owner, LineClient& observer) {
  REQUIRE(owner.request("StartMv 20 0 0") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(observer.until_prefix("State jog", 2.0));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
}
}  // namespace

TEST_CASE("the jogging owner closes its connection: the machine stops at once") {
  DaemonProcess messd;
  LineClient observer(messd.port());
  auto owner = std::make_unique<LineClient>(messd.port());
  start_jog(*owner, observer);
  auto t0 = Clock::now();
  owner->close_now();
  REQUIRE(observer.until_prefix("State idle", 2.0));
  CHECK(Clock::now() - t0 < std::chrono::milliseconds(500));
  CHECK(std::find(observer.seen().begin(), observer.seen().end(), "Control none") != observer.seen().end());
  require_standing(observer);
}

TEST_CASE("the jogging owner's connection is reset (RST): the machine stops at once") {
  DaemonProcess messd;
  LineClient observer(messd.port());
  LineClient owner(messd.port());
  start_jog(owner, observer);
  auto t0 = Clock::now();
  owner.reset();
  REQUIRE(observer.until_prefix("State idle", 2.0));
  CHECK(Clock::now() - t0 < std::chrono::milliseconds(500));
  require_standing(observer);
}

TEST_CASE("Watch 250: silence of the owner stops the jog, keep-alives keep it going") {
  DaemonProcess messd;
  LineClient observer(messd.port());
  LineClient owner(messd.port());
  REQUIRE(owner.request("Watch 250") == std::optional<std::string>("Ok Watch"));
  start_jog(owner, observer);  // 200 ms of silence already
  // Blank lines every 100 ms for a second: still jogging.
  for (int i = 0; i < 10; ++i) {
    owner.send("");
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  auto status = observer.request("Status");
  REQUIRE(status);
  CHECK(status_field(*status, "State") == "jog");
  // Now silence: stopped between 250 ms and a few cycles later.
  auto t0 = Clock::now();
  REQUIRE(observer.until_prefix("State idle", 3.0));
  auto silent = Clock::now() - t0;
  CHECK(silent > std::chrono::milliseconds(150));
  CHECK(silent < std::chrono::milliseconds(700));
  CHECK(starts_with(owner.until_prefix("Warn WatchExpired", 2.0), "Warn WatchExpired"));
  require_standing(observer);
  // The owner keeps control: its next command re-arms the dead-man.
  CHECK(owner.request("StartMv 0 20 0") == std::optional<std::string>("Ok StartMv"));
  CHECK(observer.until_prefix("State idle", 3.0));
}

TEST_CASE("Watch takes 0 or 50 to 60000 ms") {
  DaemonProcess messd;
  LineClient c(messd.port());
  CHECK(starts_with(c.request("Watch 10"), "Err 105 "));
  CHECK(starts_with(c.request("Watch 60001"), "Err 105 "));
  CHECK(starts_with(c.request("Watch 2.5e2"), "Ok Watch"));
  CHECK(starts_with(c.request("Watch"), "Err 101 "));
  CHECK(c.request("Watch 0") == std::optional<std::string>("Ok Watch"));
}
