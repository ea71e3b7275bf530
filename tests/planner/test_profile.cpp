// The trapezoid: worked figures and the shape of the piecewise profile.
#include <catch2/catch.hpp>

#include "imess/planner/profile.hpp"

using namespace imess::planner;

TEST_CASE("trapezoid: 100 mm at 100 mm/s with 1000 mm/s² takes 1.1 s rest to rest") {
  const Trapezoid t = plan_trapezoid(100, 0, 100, 0, 1000);
  CHECK(t.vc == Approx(100));
  CHECK(t.t_acc == Approx(0.1));
  CHECK(t.t_dec == Approx(0.1));
  CHECK(t.t_cruise == Approx(0.9));
  const Profile p = trapezoid_profile(100, t);
  CHECK(p.duration == Approx(1.1));
  CHECK(p.count == 3);
  CHECK(p.at(0.05).s == Approx(0.5 * 1000 * 0.05 * 0.05));
  CHECK(p.at(0.55).v == Approx(100));
  CHECK(p.at(1.1).s == 100);  // exactly L at the end
  CHECK(p.at(1.1).v == Approx(0).margin(1e-9));
  CHECK(p.at(5).s == 100);
}

TEST_CASE("trapezoid: too short to reach the cruise speed gives a triangle") {
  // 1 mm at 1000 mm/s²: peak √(a·L) = 31.6 mm/s, 2·√(L/a) = 63.2 ms.
  const Trapezoid t = plan_trapezoid(1, 0, 100, 0, 1000);
  CHECK(t.vc == Approx(std::sqrt(1000.0)));
  CHECK(t.t_cruise == 0);
  const Profile p = trapezoid_profile(1, t);
  CHECK(p.duration == Approx(2 * std::sqrt(1 / 1000.0)));
  CHECK(p.at(p.duration / 2).s == Approx(0.5));
}

TEST_CASE("trapezoid: entry and exit speeds are kept, the length is exact") {
  const Trapezoid t = plan_trapezoid(10, 20, 80, 50, 500);
  CHECK(t.v0 == 20);
  CHECK(t.v1 == 50);
  const Profile p = trapezoid_profile(10, t);
  CHECK(p.at(0).v == Approx(20));
  CHECK(p.at(p.duration).v == Approx(50));
  // Distance of the pieces adds up to L.
  const double d = (t.vc * t.vc - 400) / 1000 + t.vc * t.t_cruise + (t.vc * t.vc - 2500) / 1000;
  CHECK(d == Approx(10));
}

TEST_CASE("trapezoid: zero length and rest profiles do not move") {
  const Profile z = trapezoid_profile(0, plan_trapezoid(0, 0, 100, 0, 1000));
  CHECK(z.duration == 0);
  CHECK(z.at(0).s == 0);
  const Profile d = rest_profile(0.25);
  CHECK(d.duration == 0.25);
  CHECK(d.at(0.1).v == 0);
  CHECK(d.at(0.1).s == 0);
}
