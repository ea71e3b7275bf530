// The analog probe's reading from the scene's signed distance and its gradient.
#include "imess/sim/analog_probe.hpp"

#include <algorithm>

namespace imess::sim {

namespace {
constexpr double kNormalStep = 1e-6;  // mm: central-difference step of the distance gradient
}

AnalogProbe::AnalogProbe(AnalogProbeConfig config, double ball_radius) noexcept
    : config_(config), ball_radius_(ball_radius), rng_(config.seed) {}

Vec3 surface_normal(const Scene& scene, const Vec3& p) noexcept {
  Vec3 g;
  for (int k = 0; k < 3; ++k) {
    Vec3 e = Vec3::Zero();
    e[k] = kNormalStep;
    g[k] = (scene.distance(p + e) - scene.distance(p - e)) / (2 * kNormalStep);
  }
  const double n = g.norm();
  return n > 0 ? Vec3(g / n) : Vec3::Zero();
}

AnalogReading AnalogProbe::read(const Scene& scene, const Vec3& centre) noexcept {
  AnalogReading r;
  r.penetration = ball_radius_ - scene.distance(centre);
  r.contact = r.penetration > 0;
  if (r.contact) {
    r.normal = surface_normal(scene, centre);
    r.over_range = r.penetration > config_.range;
    const double measured = std::min(r.penetration, config_.range);
    r.deflection = measured * r.normal;
    r.force = config_.spring_rate * measured;
  }
  if (config_.noise > 0)
    for (int k = 0; k < 3; ++k) r.deflection[k] += config_.noise * noise_(rng_);
  return r;
}

}  // namespace imess::sim
