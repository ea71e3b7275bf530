// CsyChain: machine ↔ MultipleArmCsy ↔ MoveableMachineCsy ↔ PartCsy, each link
// child = R·parent + (x0, y0, z0) with R the Euler rotation psi (z), theta (new x), phi (new z).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "imess/ippdme/csy.hpp"

using namespace imess::ippdme;

namespace {
void check_near(const Point3& a, const Point3& b, double tol = 1e-9) {
  for (int i = 0; i < 3; ++i) CHECK(std::abs(a[i] - b[i]) <= tol);
}
}  // namespace

TEST_CASE("csy: the NIST server's example: offset (5, 6, 7), no rotation, machine (2, 3, 4) reads (7, 9, 11)") {
  CsyChain c;
  c.set(CsyTarget::PartCsy, {5, 6, 7, 0, 0, 0});
  c.select(CoordSystem::PartCsy);
  check_near(c.from_machine({2, 3, 4}), {7, 9, 11});
  check_near(c.to_machine({7, 9, 11}), {2, 3, 4});
  c.select(CoordSystem::MachineCsy);
  check_near(c.from_machine({2, 3, 4}), {2, 3, 4});
}

TEST_CASE("csy: psi turns about Z, theta about the new X, phi about the new Z (coordinates, not points)") {
  CsyLink psi({0, 0, 0, 0, 90, 0});
  check_near(psi.to_child({1, 0, 0}), {0, -1, 0});  // the X axis lies along −Y of the turned frame
  CsyLink theta({0, 0, 0, 90, 0, 0});
  check_near(theta.to_child({0, 1, 0}), {0, 0, -1});
  CsyLink both({0, 0, 0, 90, 90, 0});
  check_near(both.to_child({1, 0, 0}), theta.to_child(psi.to_child({1, 0, 0})));
  CsyLink phi({0, 0, 0, 0, 0, 90});
  check_near(phi.to_child({1, 0, 0}), psi.to_child({1, 0, 0}));
}

TEST_CASE("csy: points and vectors go there and back through the whole chain (seeded random frames)") {
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> pos(-500, 500), ang(0, 360), th(0, 180);
  for (int k = 0; k < 200; ++k) {
    CsyChain c;
    c.set(CsyTarget::MultipleArmCsy, {pos(rng), pos(rng), pos(rng), th(rng), ang(rng), ang(rng)});
    c.set(CsyTarget::MoveableMachineCsy, {pos(rng), pos(rng), pos(rng), th(rng), ang(rng), ang(rng)});
    c.set(CsyTarget::PartCsy, {pos(rng), pos(rng), pos(rng), th(rng), ang(rng), ang(rng)});
    c.select(static_cast<CoordSystem>(k % 4));
    const Point3 p{pos(rng), pos(rng), pos(rng)}, v{pos(rng), pos(rng), pos(rng)};
    check_near(c.to_machine(c.from_machine(p)), p, 1e-8);
    check_near(c.vector_to_machine(c.vector_from_machine(v)), v, 1e-8);
    // A rotation keeps lengths; a vector is not shifted.
    const Point3 w = c.vector_from_machine(v);
    CHECK(std::hypot(w[0], w[1], w[2]) == Approx(std::hypot(v[0], v[1], v[2])).epsilon(1e-12));
    const Point3 a = c.from_machine(p), b = c.from_machine({p[0] + v[0], p[1] + v[1], p[2] + v[2]});
    check_near({b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w, 1e-8);
  }
}

TEST_CASE("csy: the Jog and Sensor systems are kept and read back, and move nothing") {
  CsyChain c;
  c.set(CsyTarget::JogDisplayCsy, {1, 2, 3, 10, 20, 30});
  CHECK(c.get(CsyTarget::JogDisplayCsy) == CsyTransformation{1, 2, 3, 10, 20, 30});
  for (auto s : {CoordSystem::MachineCsy, CoordSystem::PartCsy}) {
    c.select(s);
    check_near(c.from_machine({4, 5, 6}), {4, 5, 6});
  }
}

TEST_CASE("csy_transformation undoes a link's rotation: any angles, and theta 0 and 180 (seeded)") {
  std::mt19937 rng(1294);
  std::uniform_real_distribution<double> angle(0, 360), tilt(0, 180), offset(-500, 500);
  auto check = [](const CsyTransformation& t) {
    const CsyLink link(t);
    double r[3][3];
    for (int j = 0; j < 3; ++j) {
      Point3 e{0, 0, 0};
      e[static_cast<std::size_t>(j)] = 1;
      const auto col = link.vector_to_child(e);
      for (int i = 0; i < 3; ++i) r[i][j] = col[static_cast<std::size_t>(i)];
    }
    const auto back = csy_transformation(r, {t.x0, t.y0, t.z0});
    CHECK(back.theta >= 0);
    CHECK(back.theta <= 180);
    CHECK(back.psi >= 0);
    CHECK(back.psi < 360);
    CHECK(back.phi >= 0);
    CHECK(back.phi < 360);
    const CsyLink again(back);  // the same mapping, whatever angles express it
    for (const Point3 p : {Point3{1, 2, 3}, Point3{-40, 7, 0.5}, Point3{0, 0, 0}}) {
      const auto a = link.to_child(p), b = again.to_child(p);
      for (std::size_t i = 0; i < 3; ++i) CHECK(std::abs(a[i] - b[i]) < 1e-9);
    }
  };
  for (int n = 0; n < 300; ++n) check({offset(rng), offset(rng), offset(rng), tilt(rng), angle(rng), angle(rng)});
  for (double theta : {0.0, 180.0, 1e-9, 179.9999999})
    for (int n = 0; n < 20; ++n) check({offset(rng), offset(rng), offset(rng), theta, angle(rng), angle(rng)});
}
