// Probe qualification: the touch plan on a reference sphere and the fit of the ball centres.
#include "qualification.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "imess/metrology/fit.hpp"

namespace imess::messcap {
namespace {

using Eigen::Vector3d;

std::string mm(double v, int decimals = 4) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

}  // namespace

TouchPlan plan_touches(const ReferenceSphere& sphere, double tip_radius, const TouchPattern& pattern) {
  if (pattern.ring_points < 3 || pattern.ring_points > 72)
    throw QualificationError("the ring needs 3 to 72 points, not " + std::to_string(pattern.ring_points));
  if (!(pattern.ring_elevation_deg >= 0 && pattern.ring_elevation_deg <= 60))
    throw QualificationError("the ring's elevation must be 0 to 60 degrees above the equator");
  if (!(pattern.clearance > 0) || !(pattern.safe_height > 0))
    throw QualificationError("the clearance and the safe height must be above 0 mm");
  if (!(sphere.diameter > 0)) throw QualificationError("the reference sphere needs a diameter above 0 mm");
  const double contact = sphere.radius() + tip_radius;  // centre of the sphere to the ball centre
  const double elevation = pattern.ring_elevation_deg * std::numbers::pi / 180;
  TouchPlan plan;
  auto add = [&](const Vector3d& outward) {
    plan.touches.push_back({sphere.centre + (contact + pattern.clearance) * outward, sphere.centre + contact * outward, -outward});
  };
  for (int k = 0; k < pattern.ring_points; ++k) {
    const double azimuth = 2 * std::numbers::pi * k / pattern.ring_points;
    add({std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)});
  }
  add(Vector3d::UnitZ());
  plan.safe_z = sphere.centre.z() + contact + pattern.safe_height;
  return plan;
}

Qualification qualify_probe(const ReferenceSphere& sphere, std::span<const metrology::ProbedPoint> hits,
                            const Vector3d& previous_offset) {
  if (hits.size() < 4)
    throw QualificationError(std::to_string(hits.size()) + " touches cannot give a sphere; at least 4 are needed");
  Qualification q;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (!hits[i].has_approach())
      throw QualificationError("touch " + std::to_string(i + 1) +
                               " has no approach direction (a ForcePt?): its ball centre is unknown");
    q.centres.push_back(hits[i].centre());
  }
  auto fit = metrology::fit_sphere(q.centres);
  if (!fit) throw QualificationError("no sphere fits the ball centres: " + fit.error().message);
  q.centre_fit = *fit;
  q.tip_radius = q.centre_fit.radius() - sphere.radius();
  if (!(q.tip_radius > 0))
    throw QualificationError("the ball centres lie on a sphere of radius " + mm(q.centre_fit.radius()) +
                             " mm, not larger than the reference sphere's " + mm(sphere.radius()) +
                             " mm: is --diameter the sphere's calibrated diameter?");
  q.shift = sphere.centre - q.centre_fit.center;
  q.offset = previous_offset + q.shift;
  q.form = q.centre_fit.stats.form();
  for (const auto& c : q.centres) q.residuals.push_back((c - q.centre_fit.center).norm() - q.centre_fit.radius());
  return q;
}

std::optional<std::string> refusal(const Qualification& q, const QualificationLimits& limits) {
  if (q.form > limits.max_form)
    return "the sphere's form error " + mm(q.form) + " mm is above the limit " + mm(limits.max_form) +
           " mm (--max-form): clean the sphere and the stylus, check the stylus is tight and that every touch met the sphere";
  if (q.tip_radius > limits.max_tip_radius)
    return "the effective tip radius " + mm(q.tip_radius) + " mm is above the " + mm(limits.max_tip_radius, 0) +
           " mm messd can compensate";
  for (int a = 0; a < 3; ++a)
    if (std::abs(q.offset[a]) > limits.max_offset)
      return std::string("the probe offset in ") + "XYZ"[a] + " " + mm(q.offset[a]) + " mm is outside messd's ±" +
             mm(limits.max_offset, 0) + " mm";
  return std::nullopt;
}

}  // namespace imess::messcap
