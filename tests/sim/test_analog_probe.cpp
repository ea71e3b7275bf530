// The simulated analog (scanning) probe against the scene's exact geometry, in virtual time: the
// carriage is driven through the cube's top and front faces, the Ø30 bore and the reference
// sphere in 0.1 ms steps (the card's sub-tick) and every step's deflection must be the
// penetration along the true surface normal (within 1 µm; in fact to rounding), zero off
// contact, clamped at the range beyond it with over_range set; a reading compensated by the tip
// radius along its normal lands on the true surface. Noise is seeded and has its configured size.
#include <cmath>
#include <numbers>
#include <vector>

#include <catch2/catch.hpp>

#include "imess/sim/analog_probe.hpp"
#include "imess/sim/mechanics.hpp"

using namespace imess;
using sim::Vec3;

namespace {

constexpr double kBall = 2.0;
constexpr double kRange = 1.0;
constexpr double kStep = 1e-4;  // s
constexpr double kMicron = 1e-3;

sim::MechanicsConfig analog_config(double noise = 0.0) {
  sim::MechanicsConfig mc;
  mc.probe.ball_radius = kBall;
  mc.probe.type = sim::ProbeType::Analog;
  mc.probe.analog.range = kRange;
  mc.probe.analog.noise = noise;
  mc.probe.analog.spring_rate = 0.4;
  return mc;
}

// Drives the carriage from `from` along unit `dir` at 5 mm/s for `travel` mm and checks every
// step's reading against the surface whose outward normal is `normal` and whose ball-contact
// position is `touch` (the ball centre where it just touches).
void drive_through(const Vec3& from, const Vec3& dir, double travel, const Vec3& touch, const Vec3& normal,
                   bool sphere = false, const Vec3& sphere_centre = Vec3::Zero()) {
  sim::MechanicsConfig mc = analog_config();
  mc.start.head<3>() = from;
  sim::Mechanics m(mc, sim::default_scene());
  for (int a = 0; a < 3; ++a) m.set_position_driven(a, true);
  const double speed = 5.0;
  int in_contact = 0, clamped = 0;
  for (int i = 1; i * speed * kStep <= travel; ++i) {
    const Vec3 c = from + dir * (i * speed * kStep);
    for (int a = 0; a < 3; ++a) m.command_position(a, c[a]);
    m.step(kStep);
    const auto& r = m.analog_reading();
    // The true penetration along the surface normal at this carriage position.
    Vec3 n = normal;
    double pen = (touch - c).dot(normal);
    if (sphere) {
      n = (c - sphere_centre).normalized();
      pen = (touch - sphere_centre).norm() - (c - sphere_centre).norm();
    }
    INFO("carriage " << c.transpose() << ", true penetration " << pen);
    if (std::abs(pen) < 1e-9) continue;  // exactly at the touch: either side is right to rounding
    REQUIRE(r.contact == (pen > 0));
    if (pen <= 0) {
      CHECK(r.deflection.norm() == 0.0);
      continue;
    }
    ++in_contact;
    CHECK(r.penetration == Approx(pen).margin(1e-9));
    CHECK((r.normal - n).norm() < 1e-6);
    const double expected = std::min(pen, kRange);
    CHECK((r.deflection - expected * n).norm() < kMicron);
    CHECK(r.force == Approx(0.4 * expected));
    CHECK(r.over_range == (pen > kRange));
    if (r.over_range) ++clamped;
    if (!r.over_range) {
      // Compensated: the deflected ball centre less the tip radius along the normal is on the surface.
      const Vec3 surface = c + r.deflection - kBall * r.normal;
      CHECK(std::abs(m.scene().distance(surface)) < kMicron);
    }
  }
  CHECK(in_contact > 100);
  CHECK(clamped > 100);
}

}  // namespace

TEST_CASE("analog probe: the cube's top face, in virtual time, deflection = penetration up to the range", "[sim][analog]") {
  // Over the top (z 80) away from the fillet: down from 82.5 through 1.8 mm of penetration.
  drive_through(Vec3(430, 330, 82.5), Vec3(0, 0, -1), 2.3, Vec3(430, 330, 82), Vec3::UnitZ());
}

TEST_CASE("analog probe: the cube's front face, turned 0.3 degrees", "[sim][analog]") {
  const double yaw = 0.3 * std::numbers::pi / 180;
  const Vec3 normal(std::sin(yaw), -std::cos(yaw), 0);          // the box's -y face, outward
  const Vec3 face(460 + 50 * std::sin(yaw), 350 - 50 * std::cos(yaw), 40);  // its centre
  const Vec3 along(std::cos(yaw), std::sin(yaw), 0);            // in the face, 10 mm off its centre
  const Vec3 touch = face + 10 * along + Vec3(0, 0, -5) + kBall * normal;
  drive_through(touch + 0.5 * normal, -normal, 2.3, touch, normal);
}

TEST_CASE("analog probe: the bore pushes the ball toward its axis", "[sim][analog]") {
  // Inside the Ø30 bore at z 40, from 12.5 mm off the axis outward along +x.
  const Vec3 axis(460, 350, 40);
  drive_through(axis + Vec3(12.5, 0, 0), Vec3::UnitX(), 2.3, axis + Vec3(15 - kBall, 0, 0), -Vec3::UnitX());
}

TEST_CASE("analog probe: the reference sphere, radially from above at 45 degrees", "[sim][analog]") {
  const Vec3 centre(750, 650, 60);
  const Vec3 dir = Vec3(1, 1, std::sqrt(2.0)).normalized();  // 45° up from the equator
  const Vec3 touch = centre + (12.5 + kBall) * dir;
  drive_through(touch + 0.5 * dir, -dir, 2.3, touch, dir, true, centre);
}

TEST_CASE("analog probe: off contact and with a trigger probe the reading is empty", "[sim][analog]") {
  sim::MechanicsConfig mc = analog_config();
  mc.start.head<3>() = Vec3(430, 330, 100);
  sim::Mechanics free_air(mc, sim::default_scene());
  CHECK_FALSE(free_air.analog_reading().contact);
  CHECK(free_air.analog_reading().deflection.norm() == 0.0);
  mc.start.head<3>() = Vec3(430, 330, 81.7);  // 0.3 mm into the top
  sim::Mechanics touching(mc, sim::default_scene());
  CHECK(touching.analog_reading().deflection.z() == Approx(0.3).margin(1e-9));
  mc.probe.type = sim::ProbeType::Trigger;
  sim::Mechanics trigger(mc, sim::default_scene());
  trigger.step(kStep);
  CHECK_FALSE(trigger.analog_reading().contact);
  CHECK(trigger.tip_contact());  // the switch still works
}

TEST_CASE("analog probe: noise is seeded and of the configured size", "[sim][analog]") {
  const sim::Scene scene = sim::default_scene();
  sim::AnalogProbeConfig cfg;
  cfg.noise = 0.002;
  cfg.seed = 7;
  sim::AnalogProbe a(cfg, kBall), b(cfg, kBall);
  const Vec3 c(430, 330, 81.7);  // 0.3 mm deflection along +z
  double sum = 0, sq = 0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const auto ra = a.read(scene, c), rb = b.read(scene, c);
    REQUIRE(ra.deflection == rb.deflection);
    const double e = ra.deflection.z() - 0.3;
    sum += e;
    sq += e * e;
    CHECK(ra.penetration == Approx(0.3).margin(1e-9));  // the truth is not noisy
  }
  const double mean = sum / n, sd = std::sqrt(sq / n - mean * mean);
  CHECK(std::abs(mean) < 4 * 0.002 / std::sqrt(double(n)));
  CHECK(sd == Approx(0.002).epsilon(0.05));
  cfg.seed = 8;
  sim::AnalogProbe other(cfg, kBall);
  CHECK(other.read(scene, c).deflection != sim::AnalogProbe(sim::AnalogProbeConfig{0.5, 0.002, 0.5, 7}, kBall).read(scene, c).deflection);
}
