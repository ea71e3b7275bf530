// Stats against a real messd: the measuring interval (Stats Reset, Stats Interval, Stats
// Hist) restarts when asked, its histogram sums to its cycles, and plain Stats keeps counting
// since the start. Counts only: no timing is asserted.
#include <catch2/catch.hpp>

#include <thread>

#include "net_fixture.hpp"

using namespace imess::test;

namespace {
std::uint64_t cycles_of(const std::optional<std::string>& line) {
  REQUIRE(line);
  return std::stoull(status_field(*line, "Cycles"));
}
// Waits until the interval holds at least n cycles.
std::optional<std::string> interval_with(LineClient& c, std::uint64_t n) {
  for (int i = 0; i < 500; ++i) {
    auto r = c.request("Stats Interval");
    if (!starts_with(r, "Ok Stats Interval ") || cycles_of(r) >= n) return r;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return std::nullopt;
}
}  // namespace

TEST_CASE("Stats Reset starts a measuring interval that Stats Interval and Stats Hist report") {
  DaemonProcess messd;
  LineClient c(messd.port());
  auto first = interval_with(c, 50);
  REQUIRE(starts_with(first, "Ok Stats Interval Period 1000 Cycles "));
  for (auto name : {"LatP50", "LatP99", "LatP999", "LatMax", "Overruns"}) CHECK_FALSE(status_field(*first, name).empty());
  CHECK(first->substr(first->size() - 11) == "Realtime no");  // --no-rt

  // Plain Stats: since the start, summarised once a second; a reset leaves it alone.
  std::optional<std::string> since;
  for (int i = 0; i < 500 && !starts_with(since, "Ok Stats Period 1000 "); ++i) {
    since = c.request("Stats");
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  REQUIRE(starts_with(since, "Ok Stats Period 1000 Cycles "));
  const auto before_reset = cycles_of(since);
  REQUIRE(c.request("Stats Reset") == std::optional<std::string>("Ok Stats Reset"));
  auto after = interval_with(c, 1);
  REQUIRE(after);
  CHECK(cycles_of(after) < before_reset);  // restarted, not still counting since the start
  std::optional<std::string> later;
  for (int i = 0; i < 500; ++i) {
    later = c.request("Stats");
    if (later && cycles_of(later) > before_reset) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  CHECK(cycles_of(later) > before_reset);  // the next summary went on from where it was

  // The histogram: one line per non-empty 1 us bucket, then the count it sums to.
  c.send("Stats Hist");
  std::uint64_t sum = 0;
  int last_bucket = -1;
  for (;;) {
    auto l = c.next(5.0);
    REQUIRE(l);
    if (l->rfind("CurrCor", 0) == 0) continue;
    if (l->rfind("Stats Hist ", 0) == 0) {
      int bucket = 0;
      unsigned long count = 0;
      REQUIRE(std::sscanf(l->c_str(), "Stats Hist %d %lu", &bucket, &count) == 2);
      CHECK(bucket > last_bucket);  // ascending, each once
      CHECK(count > 0);
      last_bucket = bucket;
      sum += count;
      continue;
    }
    REQUIRE(starts_with(l, "Ok Stats Hist Cycles "));
    CHECK(cycles_of(l) == sum);
    CHECK_FALSE(status_field(*l + " ", "Overruns").empty());
    break;
  }
  CHECK(sum > 0);
}
