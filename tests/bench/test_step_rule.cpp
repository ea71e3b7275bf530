// The step rate a base thread's jitter allows: whole base periods for the drive's minimum
// step length and space plus the jitter, one step per pulse and space.
#include <catch2/catch.hpp>

#include "step_rule.hpp"

using imess::bench::step_rate;

TEST_CASE("without jitter a pulse and a space of one period each: one step per two periods") {
  const auto r = step_rate(25, 0, 5, 5);
  CHECK(r.len_periods == 1);
  CHECK(r.space_periods == 1);
  CHECK(r.steps_per_s == Approx(20000));
}

TEST_CASE("jitter that would cut a pulse below the drive's minimum takes another period") {
  // 25 us periods, 5 us minimum: 19 us of jitter still leaves 6 us, 21 us leaves 4 us.
  CHECK(step_rate(25, 19, 5, 5).len_periods == 1);
  const auto r = step_rate(25, 21, 5, 5);
  CHECK(r.len_periods == 2);
  CHECK(r.space_periods == 2);
  CHECK(r.steps_per_s == Approx(10000));
  // exactly on the edge: 20 us of jitter leaves exactly 5 us
  CHECK(step_rate(25, 20, 5, 5).len_periods == 1);
}

TEST_CASE("length and space are priced separately, and large jitter costs many periods") {
  const auto r = step_rate(50, 120, 2, 10);
  CHECK(r.len_periods == 3);    // 122 us
  CHECK(r.space_periods == 3);  // 130 us
  CHECK(r.steps_per_s == Approx(1e6 / 300));
  CHECK(step_rate(50, 0, 60, 1).len_periods == 2);
  CHECK(step_rate(50, -3, 1, 1).len_periods == 1);  // a negative spread is no jitter
}
