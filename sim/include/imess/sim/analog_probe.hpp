// The analog (measuring, scanning) probe of the simulated machine: while the ball touches the
// scene it reports a deflection vector — how far, and which way, the surface has pushed the
// stylus out of its rest position — instead of a switch edge. Read once per simulated cycle;
// docs/scanning.md says how the servo card's link and the core will carry it.
//
// Geometry: the carriage holds the ball centre's rest position c. The scene's signed distance
// d(c) (positive outside material) and its outward unit normal n there give the penetration
// p = ball_radius - d(c); in contact (p > 0) the stylus is pushed out along n, so the deflection is
// p n, clamped at the probe's range, plus Gaussian noise (per component, seeded). The deflected
// ball centre is c + p n and the surface point it touches c - d(c) n: a reading compensates to
// the true surface exactly when it is within range and without noise.
#pragma once
#include <cstdint>
#include <random>

#include "imess/sim/scene.hpp"

namespace imess::sim {

enum class ProbeType { Trigger, Analog };

struct AnalogProbeConfig {
  double range = 1.0;        // mm: the largest deflection the probe measures (clamped beyond)
  double noise = 0.0;        // mm: standard deviation of the reading's noise, per component
  double spring_rate = 0.5;  // N/mm: the stylus' spring (force = rate x deflection)
  std::uint64_t seed = 1;    // the noise generator's seed: runs repeat exactly
};

struct AnalogReading {
  bool contact = false;            // the ball touches material (penetration > 0)
  bool over_range = false;         // the penetration exceeds the range: deflection clamped
  double penetration = 0.0;        // mm, the true one (not clamped, no noise); <= 0 off contact
  Vec3 normal = Vec3::Zero();      // the outward surface normal at the contact (unit; 0 off contact)
  Vec3 deflection = Vec3::Zero();  // mm, the measured deflection: clamped, with noise
  double force = 0.0;              // N: spring_rate x |deflection|, without noise
};

class AnalogProbe {
 public:
  AnalogProbe(AnalogProbeConfig config, double ball_radius) noexcept;
  // The reading with the ball's rest centre at `centre` in `scene`. No allocation.
  AnalogReading read(const Scene& scene, const Vec3& centre) noexcept;
  const AnalogProbeConfig& config() const noexcept { return config_; }

 private:
  AnalogProbeConfig config_;
  double ball_radius_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> noise_{0.0, 1.0};
};

// The outward unit normal of the scene's surface nearest to p: the normalised gradient of the
// signed distance (central differences over 1e-6 mm). Zero where the gradient vanishes.
Vec3 surface_normal(const Scene& scene, const Vec3& p) noexcept;

}  // namespace imess::sim
