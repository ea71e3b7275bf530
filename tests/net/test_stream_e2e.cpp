// The position stream against a real messd: a client's own Stream rate beside the shared
// ReportHz, its bounds, and the first change after rest pushed at once whatever the rate.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <chrono>
#include <optional>
#include <string>

#include <unistd.h>

#include "net_fixture.hpp"

using namespace imess::test;
using Clock = std::chrono::steady_clock;

namespace {

// CurrCor lines a client receives in `seconds` (everything else is skipped).
int curr_cor_lines(LineClient& c, double seconds) {
  int n = 0;
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < end) {
    const double left = std::chrono::duration<double>(end - Clock::now()).count();
    if (auto l = c.next(left); l && l->rfind("CurrCor ", 0) == 0) ++n;
  }
  return n;
}

}  // namespace

TEST_CASE("a client's Stream rate is its own: the other clients keep ReportHz") {
  DaemonProcess messd;
  LineClient owner(messd.port()), fast(messd.port()), shared(messd.port());
  REQUIRE(fast.until_prefix("CurrCor", 2.0));
  REQUIRE(shared.until_prefix("CurrCor", 2.0));
  REQUIRE(fast.request("Stream 500") == std::optional<std::string>("Ok Stream 500"));
  REQUIRE(owner.request("Take") == std::optional<std::string>("Ok Take"));
  REQUIRE(owner.request("StartMv 20 0 0") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(fast.until_prefix("CurrCor", 2.0));  // moving
  const int fast_lines = curr_cor_lines(fast, 1.0);
  while (shared.next(0.01)) {}  // what arrived meanwhile: the next second is counted afresh
  const int shared_lines = curr_cor_lines(shared, 1.0);
  REQUIRE(owner.request("StopMv") == std::optional<std::string>("Ok StopMv"));
  INFO("Stream 500: " << fast_lines << " lines/s, ReportHz 10: " << shared_lines << " lines/s");
  CHECK(shared_lines <= 12);               // ReportHz 10 (a first-change push and a tick at the edges)
  CHECK(fast_lines >= 5 * shared_lines);   // 500 Hz asked; a loaded host still gives far more than 10
  CHECK(fast_lines <= 520);
}

TEST_CASE("Stream takes 0.1 Hz up to the motion loop's rate, 0 returns to ReportHz") {
  DaemonProcess messd;
  LineClient c(messd.port());
  CHECK(c.request("Stream 1000") == std::optional<std::string>("Ok Stream 1000"));  // Period 1000 us
  auto faster = c.request("Stream 1500");
  REQUIRE(faster);
  CHECK(faster->rfind("Err 105 Stream 1500 Hz is faster than the motion loop (1000 Hz, Period 1000 us)", 0) == 0);
  auto slow = c.request("Stream 0.05");
  REQUIRE(slow);
  CHECK(slow->rfind("Err 105 ", 0) == 0);
  CHECK(c.request("Stream -3")->rfind("Err 105 ", 0) == 0);
  CHECK(c.request("Stream 0") == std::optional<std::string>("Ok Stream 10"));  // the shared ReportHz
  CHECK(c.request("Set ReportHz 25") == std::optional<std::string>("Ok Set"));
  CHECK(c.request("Stream 0") == std::optional<std::string>("Ok Stream 25"));
}

TEST_CASE("the first position change after rest arrives at once, not at the next report tick") {
  DaemonProcess messd;
  LineClient owner(messd.port());
  REQUIRE(owner.until_prefix("CurrCor", 2.0));
  // One report every 10 s from the next tick (at most 100 ms away) on: at that tick the
  // machine has been at rest, and the tick after it is 10 s later — without the push at the
  // start of motion the jog would show only then.
  REQUIRE(owner.request("Set ReportHz 0.1") == std::optional<std::string>("Ok Set"));
  REQUIRE(owner.request("Take") == std::optional<std::string>("Ok Take"));
  usleep(300'000);
  const auto t0 = Clock::now();
  REQUIRE(owner.request("StartMv 10 0 0") == std::optional<std::string>("Ok StartMv"));
  REQUIRE(owner.until_prefix("CurrCor", 5.0));
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  INFO("the first CurrCor after " << ms << " ms");
  CHECK(ms < 1000);
  REQUIRE(owner.request("StopMv") == std::optional<std::string>("Ok StopMv"));
}

namespace {
// Sleeps that ended in a wake-up, summed over messd's threads except the motion loop's.
long io_wakeups(pid_t pid) {
  long sum = 0;
  const std::string dir = "/proc/" + std::to_string(pid) + "/task";
  for (const auto& task : std::filesystem::directory_iterator(dir)) {
    std::ifstream comm(task.path() / "comm");
    std::string name;
    std::getline(comm, name);
    if (name == "messd-motion") continue;
    std::ifstream status(task.path() / "status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("voluntary_ctxt_switches:", 0) == 0) sum += std::stol(line.substr(24));
  }
  return sum;
}
}  // namespace

TEST_CASE("standing messd's io thread sleeps between events (no millisecond polling) and a hand push still shows at once") {
  DaemonProcess messd;
  LineClient owner(messd.port());
  REQUIRE(owner.until_prefix("CurrCor", 2.0));
  REQUIRE(owner.request("Set ReportHz 0.1") == std::optional<std::string>("Ok Set"));
  REQUIRE(owner.request("Take") == std::optional<std::string>("Ok Take"));
  REQUIRE(owner.request("Watch 5000") == std::optional<std::string>("Ok Watch"));  // the dead-man has a deadline, not a poll
  usleep(300'000);
  const long before = io_wakeups(messd.pid());
  usleep(2'000'000);
  const double per_s = (io_wakeups(messd.pid()) - before) / 2.0;
  INFO("io wake-ups a second, standing: " << per_s);
  CHECK(per_s < 200);  // timers at 20 Hz and below; polling each millisecond would be 1000
  const auto t0 = Clock::now();
  REQUIRE(owner.request("HandMv 0 0 -5") == std::optional<std::string>("Ok HandMv"));  // loops open, pushed by hand
  REQUIRE(owner.until_prefix("CurrCor", 5.0));
  const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  INFO("the first CurrCor of the hand push after " << ms << " ms");
  CHECK(ms < 1000);  // the next report tick is 10 s away
}
