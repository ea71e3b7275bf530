// Arcs in every plane: the principal planes (XY, ZX, YZ as G17/G18/G19), tilted normals,
// planes through other linear axes, helices and extra turns. Every sample of the run lies
// on the helix (radius, and the lead along the normal proportional to the swept angle),
// other axes move in proportion, every axis keeps its limits, and the travel check refuses
// exactly the arcs whose path leaves the box (seeded random property).
#include <catch2/catch.hpp>

#include <numbers>

#include <Eigen/Geometry>

#include "planner_rig.hpp"

using namespace imess::test;
using Eigen::Vector3d;

namespace {

// An arc given by its geometry: centre c in the plane axes, unit normal n, radius r, the
// start at angle 0 (along e1), swept angle phi (signed about n, |phi| may exceed 2π), lead
// h along n, and the other axes' displacement.
struct HelixSpec {
  std::array<std::int8_t, 3> axes{0, 1, 2};
  Vector3d c{0, 0, 0}, n{0, 0, 1}, e1{1, 0, 0};
  double r = 10, phi = std::numbers::pi / 2, h = 0;
  Pose other{};  // displacement of the axes outside the plane
  double feed = 50;

  Vector3d e2() const { return n.cross(e1); }
  Vector3d point(double theta) const {
    return c + r * (std::cos(theta) * e1 + std::sin(theta) * e2()) + h * theta / phi * n;
  }
  Pose pose(const Pose& start, double theta) const {
    Pose p = start;
    for (int i = 0; i < kMaxAxes; ++i) p[i] += theta / phi * other[i];
    const Vector3d q = point(theta);
    for (int k = 0; k < 3; ++k) p[axes[k]] = q[k];
    return p;
  }
  Arc request(std::uint32_t id, const Pose& start) const {
    Arc a;
    a.id = id;
    a.target = pose(start, phi);
    for (int k = 0; k < 3; ++k) a.centre[k] = c[k], a.normal[k] = n[k];
    a.plane_axes = axes;
    a.ccw = phi > 0;
    a.turns = static_cast<int>(std::floor(std::fabs(phi) / (2 * std::numbers::pi)));
    a.feed = feed;
    return a;
  }
};

// The start pose of a spec (other axes at `base`).
Pose start_of(const HelixSpec& s, Pose base) { return s.pose(base, 0); }

// Every tick on the helix: radius r about the axis through c along n, the lead along n
// equal to h·θ/φ with θ unwrapped from tick to tick, other axes at the same fraction.
// Returns the largest deviation seen (mm).
double check_on_helix(const HelixSpec& s, const Pose& start, const RunResult& r) {
  double theta = 0, worst = 0;
  for (const auto& t : r.ticks) {
    Vector3d p(t.pose[s.axes[0]], t.pose[s.axes[1]], t.pose[s.axes[2]]);
    const Vector3d q = p - s.c;
    const double along = q.dot(s.n);
    const Vector3d radial = q - along * s.n;
    const double a = std::atan2(radial.dot(s.e2()), radial.dot(s.e1));
    theta += std::remainder(a - theta, 2 * std::numbers::pi);  // unwrap: the step per tick is far below π
    worst = std::max(worst, std::fabs(radial.norm() - s.r));
    worst = std::max(worst, std::fabs(along - s.h * theta / s.phi));
    const double f = theta / s.phi;
    for (int i = 0; i < kMaxAxes; ++i)
      if (i != s.axes[0] && i != s.axes[1] && i != s.axes[2])
        worst = std::max(worst, std::fabs(t.pose[i] - (start[i] + f * s.other[i])));
  }
  CHECK(theta == Approx(s.phi).margin(1e-9));  // swept exactly the asked angle, turns included
  return worst;
}

Machine uneven_machine(const char* letters) {
  Machine m = make_machine(letters, -500, 500, 100, 1000);
  for (int i = 0; i < m.count; ++i) {
    m.axes[i].max_velocity = 60 + 20 * i;
    m.axes[i].max_accel = 600 + 150 * i;
  }
  return m;
}

void run_and_check(const Machine& m, const HelixSpec& s, const Pose& base = {}) {
  Planner p(m);
  const Pose start = start_of(s, base);
  p.set_position(start);
  const auto r = run(p, {s.request(1, start)});
  REQUIRE(r.segments.size() == 1);
  CHECK(r.segments[0].kind == SegmentKind::Arc);
  CHECK(r.segments[0].length == Approx(std::hypot(s.r * s.phi, s.h)));
  CHECK(check_on_helix(s, start, r) < 1e-9);
  CHECK(r.ticks.back().pose == s.request(1, start).target);  // the end exactly
  check_limits(m, r);
}
}  // namespace

TEST_CASE("arc planes: XY, ZX and YZ (G17/G18/G19 normals), both ways, with helix and turns") {
  const Machine m = uneven_machine("XYZ");
  struct Plane {
    const char* name;
    Vector3d n, e1;
  };
  // G18's plane is ZX: counter-clockwise about +Y turns Z toward X.
  const Plane planes[] = {{"XY", {0, 0, 1}, {1, 0, 0}}, {"ZX", {0, 1, 0}, {0, 0, 1}}, {"YZ", {1, 0, 0}, {0, 1, 0}}};
  for (const auto& pl : planes)
    for (double phi : {std::numbers::pi / 2, -std::numbers::pi / 2, 1.5 * std::numbers::pi, -(2 * std::numbers::pi + 1), 2 * (2 * std::numbers::pi) + 0.3})
      for (double h : {0.0, 7.5, -3.0}) {
        DYNAMIC_SECTION(pl.name << " phi " << phi << " h " << h) {
          HelixSpec s;
          s.n = pl.n;
          s.e1 = pl.e1;
          s.c = {20, -30, 40};
          s.r = 12;
          s.phi = phi;
          s.h = h;
          run_and_check(m, s);
        }
      }
}

TEST_CASE("arc planes: the sense of rotation of the principal planes is G-code's") {
  // From the start on the first axis of the plane, a quarter turn counter-clockwise reaches
  // the second: XY: X → Y; ZX: Z → X; YZ: Y → Z. The centre is the origin, radius 10.
  struct Case {
    Vector3d n, start, quarter;
  };
  const Case cases[] = {{{0, 0, 1}, {10, 0, 0}, {0, 10, 0}},
                        {{0, 1, 0}, {0, 0, 10}, {10, 0, 0}},
                        {{1, 0, 0}, {0, 10, 0}, {0, 0, 10}}};
  for (const auto& c : cases) {
    Planner p(make_machine("XYZ", -100, 100, 100, 1000));
    p.set_position(pose_of({c.start[0], c.start[1], c.start[2]}));
    Arc a;
    a.id = 1;
    a.target = pose_of({c.quarter[0], c.quarter[1], c.quarter[2]});
    a.normal = {c.n[0], c.n[1], c.n[2]};
    a.ccw = true;
    a.feed = 20;
    p.append(a);
    p.flush();
    PlannedSegment s;
    REQUIRE(p.take(s));
    CHECK(s.length == Approx(10 * std::numbers::pi / 2));  // a quarter, not three quarters
  }
}

TEST_CASE("arc planes: a tilted normal with a helix, and a plane through X Y and U with Z and V along") {
  SECTION("tilted") {
    HelixSpec s;
    s.n = Vector3d(1, 2, 2).normalized();
    s.e1 = s.n.cross(Vector3d(0, 0, 1)).normalized();
    s.c = {10, 20, 30};
    s.r = 25;
    s.phi = -(2 * std::numbers::pi + 2);
    s.h = 15;
    run_and_check(uneven_machine("XYZ"), s);
  }
  SECTION("plane axes X Y U on an XYZUV machine, Z and V move linearly") {
    HelixSpec s;
    s.axes = {0, 1, 3};
    s.n = Vector3d(0, 1, 1).normalized();
    s.e1 = Vector3d(1, 0, 0);
    s.c = {0, 50, -20};
    s.r = 30;
    s.phi = 1.2;
    s.h = -4;
    s.other[2] = 12;   // Z
    s.other[4] = -40;  // V
    run_and_check(uneven_machine("XYZUV"), s, pose_of({0, 0, 5, 0, 60}));
  }
}

TEST_CASE("arc planes: refusals say what was wrong and what is accepted") {
  Planner p(make_machine("XYZ", -100, 100, 100, 1000));
  p.set_position(pose_of({10, 0, 0}));
  Arc a;
  a.id = 9;
  a.target = pose_of({0, 10, 0});
  a.feed = 20;
  SECTION("zero normal") {
    a.normal = {0, 0, 0};
    const auto r = p.append(a);
    CHECK(r.error == PlanError::ArcZeroNormal);
    CHECK(describe(r, p.machine()) == "segment 9: arc plane normal must be a finite non-zero vector");
  }
  SECTION("centre on the start") {
    a.centre = {10, 0, 0};
    CHECK(describe(p.append(a), p.machine()) == "segment 9: arc centre lies on the start point: the radius must be > 0");
  }
  SECTION("radius mismatch names the tolerance") {
    a.target = pose_of({0, 10.5, 0});
    const auto r = p.append(a);
    CHECK(r.error == PlanError::ArcRadiusMismatch);
    CHECK(r.value == Approx(0.5));
    CHECK(r.limit == Approx(0.01));  // 0.1 % of r = 10 would be 0.01 > 0.002
    CHECK(describe(r, p.machine()) ==
          "segment 9: arc end is not on the circle: its radius differs from the start's by 0.500000 (accepted: up to "
          "0.010000)");
  }
  SECTION("a planar arc refuses an end off its plane; the same end is a helix otherwise") {
    a.target = pose_of({0, 10, 0.5});
    a.planar = true;
    const auto r = p.append(a);
    CHECK(r.error == PlanError::ArcOffPlane);
    CHECK(r.value == Approx(0.5));
    CHECK(describe(r, p.machine()) ==
          "segment 9: arc end is 0.500000 off the plane through the start (accepted: up to 0.010000; a planar arc has "
          "no helix)");
    a.target = pose_of({0, 10, 0.005});
    CHECK(p.append(a).ok());  // within the tolerance
    a.planar = false;
    a.target = pose_of({10, 0, 0.5});
    a.centre = {0, 0, 0};
    CHECK(p.append(a).ok());
  }
  SECTION("negative turns") {
    a.turns = -1;
    CHECK(p.append(a).error == PlanError::ArcBadTurns);
  }
  SECTION("a centre that is not a number") {
    a.centre = {std::nan(""), 0, 0};
    CHECK(p.append(a).error == PlanError::BadPose);
  }
}

TEST_CASE("arc planes: random planes, helices and turns stay on the helix and within every limit") {
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  const Machine m = uneven_machine("XYZUV");
  for (int trial = 0; trial < 40; ++trial) {
    INFO("trial " << trial);
    HelixSpec s;
    const int linear[] = {0, 1, 2, 3, 4};
    std::array<int, 5> pick{0, 1, 2, 3, 4};
    std::shuffle(pick.begin(), pick.end(), rng);
    for (int k = 0; k < 3; ++k) s.axes[k] = static_cast<std::int8_t>(linear[pick[k]]);
    do s.n = Vector3d(u(rng), u(rng), u(rng)); while (s.n.norm() < 0.2);
    s.n.normalize();
    s.e1 = s.n.unitOrthogonal();
    s.e1 = Eigen::AngleAxisd(std::numbers::pi * u(rng), s.n) * s.e1;
    s.c = Vector3d(100 * u(rng), 100 * u(rng), 100 * u(rng));
    s.r = 1 + 40 * unit(rng);
    const int turns = static_cast<int>(3 * unit(rng));
    const double sweep = 0.2 + (2 * std::numbers::pi - 0.4) * unit(rng) + 2 * std::numbers::pi * turns;
    s.phi = unit(rng) < 0.5 ? sweep : -sweep;
    s.h = unit(rng) < 0.3 ? 0 : 30 * u(rng);
    for (int k = 3; k < 5; ++k) s.other[pick[k]] = unit(rng) < 0.5 ? 0 : 20 * u(rng);
    s.feed = 5 + 150 * unit(rng);
    run_and_check(m, s);
  }
}

TEST_CASE("arc planes: the travel check refuses exactly the arcs whose path leaves the box") {
  // Seeded random arcs near the box edges, ends inside: the planner's verdict matches a
  // dense sampling of the path (20 000 points) except within 1 µm of a travel end.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
  const Machine m = make_machine("XYZ", 0, 100, 100, 1000);
  int refused = 0, accepted = 0, bulging = 0;
  for (int trial = 0; trial < 400; ++trial) {
    HelixSpec s;
    do s.n = Vector3d(u(rng), u(rng), u(rng)); while (s.n.norm() < 0.2);
    s.n.normalize();
    s.e1 = Eigen::AngleAxisd(std::numbers::pi * u(rng), s.n) * s.n.unitOrthogonal();
    s.r = 5 + 30 * unit(rng);
    s.c = Vector3d(50 + 40 * u(rng), 50 + 40 * u(rng), 50 + 40 * u(rng));
    s.phi = (unit(rng) < 0.5 ? 1 : -1) * (0.3 + 5.5 * unit(rng) + (unit(rng) < 0.2 ? 2 * std::numbers::pi : 0));
    s.h = unit(rng) < 0.5 ? 0 : 20 * u(rng);
    const Pose start = start_of(s, {});
    const Pose end = s.pose({}, s.phi);
    bool ends_inside = true;
    for (int a = 0; a < 3; ++a) ends_inside = ends_inside && start[a] >= 0 && start[a] <= 100 && end[a] >= 0 && end[a] <= 100;
    if (!ends_inside) continue;
    double out = -1e9;  // how far the densest sampling goes beyond the box (negative: inside)
    for (int i = 0; i <= 20000; ++i) {
      const Vector3d q = s.point(s.phi * i / 20000.0);
      for (int a = 0; a < 3; ++a) out = std::max({out, -q[a], q[a] - 100});
    }
    if (std::fabs(out) < 1e-3) continue;  // too close to call by sampling
    Planner p(m);
    p.set_position(start);
    const auto r = p.append(s.request(static_cast<std::uint32_t>(trial + 1), start));
    INFO("trial " << trial << " out " << out << " " << describe(r, m));
    if (out > 0) {
      ++bulging;
      CHECK(r.error == PlanError::OutOfTravel);
      CHECK(r.id == static_cast<std::uint32_t>(trial + 1));
      ++refused;
    } else {
      CHECK(r.ok());
      ++accepted;
    }
  }
  CHECK(bulging >= 20);  // the property saw arcs that leave the box between inside ends
  CHECK(accepted >= 20);
  CHECK(refused == bulging);
}
