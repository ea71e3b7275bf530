// TrapezoidPlanner (host planners and the emulated card firmware): ends exactly on target,
// respects vmax/amax, retargets while moving.
#include <catch2/catch.hpp>

#include <cmath>

#include "imess/hal/trapezoid_planner.hpp"

using imess::hal::TrapezoidPlanner;

TEST_CASE("a move ends exactly on the target without exceeding speed or acceleration") {
  for (double dist : {0.001, 0.5, 10.0, 500.0, -123.4}) {
    TrapezoidPlanner p;
    p.reset(0);
    p.start(dist, 100, 1000);
    double dt = 1e-4, prev_v = 0, t = 0;
    while (!p.done() && t < 20) {
      p.step(dt);
      t += dt;
      REQUIRE(std::abs(p.velocity()) <= 100 + 1e-9);
      REQUIRE(std::abs(p.velocity() - prev_v) <= 1000 * dt + 1e-9);
      REQUIRE(std::abs(p.position()) <= std::abs(dist) + 1e-9);  // never overshoots
      prev_v = p.velocity();
    }
    INFO("distance " << dist);
    REQUIRE(p.done());
    CHECK(p.position() == dist);
    // Roughly the ideal trapezoid time.
    double a = 1000, v = 100, d = std::abs(dist);
    double ideal = d > v * v / a ? d / v + v / a : 2 * std::sqrt(d / a);
    CHECK(t == Approx(ideal).margin(0.01));
  }
}

TEST_CASE("stop brakes to rest and a new target from speed reverses cleanly") {
  TrapezoidPlanner p;
  p.reset(0);
  p.start(1000, 100, 1000);
  for (int i = 0; i < 5000; ++i) p.step(1e-4);  // 0.5 s: at full speed
  REQUIRE(p.velocity() == Approx(100));
  p.start(p.position() - 10, 10, 1000);  // retract behind us
  for (int i = 0; i < 50000 && !p.done(); ++i) p.step(1e-4);
  REQUIRE(p.done());
  CHECK(p.velocity() == 0);
  p.start(2000, 100, 1000);
  for (int i = 0; i < 2000; ++i) p.step(1e-4);
  double before = p.position();
  p.stop(1000);
  for (int i = 0; i < 20000 && !p.done(); ++i) p.step(1e-4);
  CHECK(p.done());
  CHECK(p.position() - before == Approx(100.0 * 100.0 / 2000 + 0.2 * 0).margin(0.02));
}

TEST_CASE("a tracked path point is not done, and stop() or start() go on from its velocity") {
  TrapezoidPlanner p;
  p.reset(0);
  p.track(10, 100);
  CHECK_FALSE(p.done());
  CHECK(p.velocity() == 100);
  p.stop(1000);
  CHECK(p.target() == Approx(15));  // 10 + 100²/(2·1000)
  double prev_v = p.velocity();
  while (!p.done()) {
    p.step(1e-4);
    REQUIRE(p.velocity() <= prev_v + 1e-12);  // braking only
    prev_v = p.velocity();
  }
  CHECK(p.position() == Approx(15).margin(1e-6));
  p.track(20, -50);
  p.start(30, 100, 1000);  // retargets from −50 mm/s: first brakes, then heads to 30
  p.step(1e-4);
  CHECK(p.velocity() == Approx(-49.9));
  while (!p.done()) p.step(1e-4);
  CHECK(p.position() == 30);
}
