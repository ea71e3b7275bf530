// TickProfile, the MRM manual's integer point-to-point profile (BRIEF §5): the manual's
// reference run, its three known faults, and a seeded property over random moves.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "imess/hal/tick_profile.hpp"

using imess::hal::TickProfile;

namespace {

struct Run {
  std::vector<std::int64_t> counts;  // per tick, as the kit's command port gets them
  std::vector<std::int64_t> speeds;  // per tick, thousandths of a count
};

Run run(TickProfile& p, std::size_t limit = 10'000'000) {
  Run r;
  while (!p.done() && r.counts.size() < limit) {
    r.counts.push_back(p.next());
    r.speeds.push_back(p.speed());
  }
  return r;
}

// The most any profile can cover in n ticks (thousandths of a count) when it starts and ends
// at rest (the first and the last tick at most one accel step), changes speed by at most
// accel per tick and never exceeds feed: tick k (1-based) at most k·a, (n + 1 − k)·a and v.
std::int64_t reach(std::int64_t n, std::int64_t feed, std::int64_t accel) {
  std::int64_t sum = 0;
  for (std::int64_t k = 1; k <= n; ++k) sum += std::min({k * accel, (n + 1 - k) * accel, feed});
  return sum;
}

// What must hold for every move: the increments add up to the distance exactly and never go
// past it, the speed stays within the feed and changes by at most accel per tick (from rest
// and to rest), and each tick sends its speed's whole counts plus at most the carried one.
void check_move(std::int64_t distance, std::int64_t feed, std::int64_t accel, const Run& r) {
  INFO("distance " << distance << " feed " << feed << " accel " << accel);
  std::int64_t sum = 0, prev = 0;
  const std::int64_t sign = distance < 0 ? -1 : 1;
  for (std::size_t k = 0; k < r.counts.size(); ++k) {
    const std::int64_t u = r.speeds[k];
    REQUIRE(u >= 1);
    REQUIRE(u <= feed);
    REQUIRE(std::abs(u - prev) <= accel);
    REQUIRE(sign * r.counts[k] >= u / TickProfile::kMilli);
    REQUIRE(sign * r.counts[k] <= u / TickProfile::kMilli + 1);
    sum += r.counts[k];
    REQUIRE(sign * sum <= sign * distance);  // never past the target
    prev = u;
  }
  CHECK(sum == distance);
  if (!r.speeds.empty()) CHECK(r.speeds.back() <= accel);  // the step down to rest is one accel step at most
}

}  // namespace

TEST_CASE("tick profile: the manual's reference run, 500 000 µm at 166.667 µm/tick and 12 µm/tick²") {
  // Counts of 1 µm; speeds in thousandths of a µm per tick.
  constexpr std::int64_t D = 500'000, V = 166'667, A = 12'000;
  TickProfile p(D, V, A);
  const Run r = run(p);
  check_move(D, V, A, r);
  REQUIRE(p.done());
  // The manual's figures with the ticks numbered from 0: the last tick is tick 3012 and the
  // first braking tick is 2999 (the first one slower than the tick before).
  CHECK(p.ticks() - 1 == 3012);
  CHECK(p.braking_from() == 2999);
  CHECK(r.speeds[2998] == V);
  CHECK(r.speeds[2999] < V);
  for (std::size_t k = 3000; k < r.speeds.size(); ++k) CHECK(r.speeds[k] <= r.speeds[k - 1]);
  // 3013 ticks (0 … 3012) is also the fewest any profile within these limits can take: in
  // 3012 ticks none reaches 500 000 µm. So "3012 ticks" counted from 1 would need a profile
  // that breaks a limit — the known fault of ending at speed.
  CHECK(reach(3012, V, A) < D * TickProfile::kMilli);
  CHECK(reach(3013, V, A) >= D * TickProfile::kMilli);
}

TEST_CASE("tick profile: the known faults — zero length, ending at speed, truncated increments") {
  // A zero-length move: done at once, no tick, nothing divided by it.
  TickProfile zero(0, 166'667, 12'000);
  CHECK(zero.done());
  CHECK(zero.next() == 0);
  CHECK(zero.ticks() == 0);

  // Ends at rest on a move too short to reach the feed, and on a one-count move.
  for (std::int64_t d : {1, 2, 7, 100, 2'000}) {
    TickProfile p(d, 166'667, 12'000);
    check_move(d, 166'667, 12'000, run(p));
  }

  // Speeds below one count per tick: truncating each tick's increment would send nothing;
  // the carried fractions send all 7 counts, one every third tick.
  TickProfile slow(7, 333, 333);
  const Run r = run(slow);
  check_move(7, 333, 333, r);
  CHECK(std::count(r.counts.begin(), r.counts.end(), 1) == 7);

  // Backwards: the same increments, negative.
  TickProfile back(-500'000, 166'667, 12'000);
  const Run b = run(back);
  check_move(-500'000, 166'667, 12'000, b);
  CHECK(back.braking_from() == 2999);

  CHECK_THROWS_AS(TickProfile(10, 0, 12), std::invalid_argument);
  CHECK_THROWS_AS(TickProfile(10, 100, 0), std::invalid_argument);
  CHECK_THROWS_AS(TickProfile(10, -5, 12), std::invalid_argument);
  CHECK_THROWS_AS(TickProfile(2'000'000'000'000, 100, 12), std::invalid_argument);
}

TEST_CASE("tick profile: random moves end exactly, within feed and accel, never past the target, as fast as the limits allow") {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    std::mt19937_64 rng(seed);
    for (int i = 0; i < 60; ++i) {
      const std::int64_t feed = std::uniform_int_distribution<std::int64_t>(1, 400'000)(rng);
      const std::int64_t accel = std::uniform_int_distribution<std::int64_t>(std::max<std::int64_t>(1, feed / 2000), 60'000)(rng);
      // At most about 40 000 ticks of cruise.
      const std::int64_t longest = std::max<std::int64_t>(1, feed * 40);
      std::int64_t distance = std::uniform_int_distribution<std::int64_t>(0, longest)(rng);
      if (rng() % 2) distance = -distance;
      INFO("seed " << seed << " move " << i);
      TickProfile p(distance, feed, accel);
      const Run r = run(p);
      REQUIRE(p.done());
      check_move(distance, feed, accel, r);
      const std::int64_t n = p.ticks();
      CHECK(n == static_cast<std::int64_t>(r.counts.size()));
      // No profile within the limits covers the distance in one tick less.
      if (n > 0) CHECK(reach(n - 1, feed, accel) < std::abs(distance) * TickProfile::kMilli);
    }
  }
}
