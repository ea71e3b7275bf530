// Tip radius compensation of features fitted to probe ball centres (see probe_compensation.hpp).
#include "imess/metrology/probe_compensation.hpp"

#include <cmath>
#include <functional>
#include <sstream>
#include <string_view>

#include <Eigen/Geometry>

#include "fit_common.hpp"
#include "imess/metrology/fit.hpp"

namespace imess::metrology {
namespace {

using NormalAt = std::function<Eigen::Vector3d(const Eigen::Vector3d& centre)>;

std::optional<FitError> check_hits(std::string_view feature, std::size_t centres,
                                   std::span<const Eigen::Vector3d> approach, double tip_radius) {
  std::ostringstream os;
  if (!std::isfinite(tip_radius) || tip_radius < 0.0) {
    os << "tip radius must be finite and >= 0, got " << tip_radius;
    return detail::make_error(FitErrorCode::InvalidArgument, feature, os.str());
  }
  if (approach.size() != centres) {
    os << "got " << centres << " ball centres but " << approach.size() << " approach vectors";
    return detail::make_error(FitErrorCode::InvalidArgument, feature, os.str());
  }
  for (std::size_t i = 0; i < approach.size(); ++i) {
    if (!approach[i].allFinite() || approach[i].norm() == 0.0) {
      os << "approach vector of hit " << i << " is zero or not finite";
      return detail::make_error(FitErrorCode::InvalidArgument, feature, os.str());
    }
  }
  return std::nullopt;
}

// +1: every decisive hit moved along the outward normal; -1: every one against it.
Fit<int> vote(std::string_view feature, std::span<const Eigen::Vector3d> centres,
              std::span<const Eigen::Vector3d> approach, double tip_radius, const NormalAt& normal_at) {
  if (auto e = check_hits(feature, centres.size(), approach, tip_radius)) return *e;
  int sign = 0;
  std::size_t first = 0;
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Eigen::Vector3d n = normal_at(centres[i]);
    if (!n.allFinite() || n.norm() == 0.0) continue;  // e.g. a centre exactly on the axis
    const double c = approach[i].normalized().dot(n.normalized());
    if (std::abs(c) < kMinApproachCosine) continue;
    const int s = c > 0.0 ? 1 : -1;
    if (sign == 0) {
      sign = s;
      first = i;
    } else if (s != sign) {
      std::ostringstream os;
      os << "hit " << i << " approached from the " << (s > 0 ? "inside" : "outside") << " but hit "
         << first << " from the " << (sign > 0 ? "inside" : "outside")
         << "; all hits of one feature must come from the same side";
      return detail::make_error(FitErrorCode::InconsistentApproach, feature, os.str());
    }
  }
  if (sign == 0)
    return detail::make_error(FitErrorCode::InconsistentApproach, feature,
                              "no hit approached the surface steeply enough to tell the material side");
  return sign;
}

Eigen::Vector3d radial(const Eigen::Vector3d& v, const Eigen::Vector3d& axis) {
  const Eigen::Vector3d a = axis.normalized();
  return v - v.dot(a) * a;
}

Fit<MaterialSide> side_from(const Fit<int>& v) {
  if (!v) return v.error();
  return *v > 0 ? MaterialSide::Inner : MaterialSide::Outer;
}

// Radius after compensation, or the error when nothing positive remains.
Fit<double> offset_radius(std::string_view feature, double radius, MaterialSide side, double r) {
  const double out = side == MaterialSide::Inner ? radius + r : radius - r;
  if (!(out > 0.0)) {
    std::ostringstream os;
    os << "an outer feature of radius " << radius << " at the ball centres is smaller than the tip radius "
       << r;
    return detail::make_error(FitErrorCode::NonPositiveSize, feature, os.str());
  }
  return out;
}

std::vector<Eigen::Vector3d> lift(std::span<const Eigen::Vector2d> v) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(v.size());
  for (const auto& p : v) out.emplace_back(p.x(), p.y(), 0.0);
  return out;
}

}  // namespace

Fit<MaterialSide> material_side(const Circle3& fit, std::span<const Eigen::Vector3d> centres,
                                std::span<const Eigen::Vector3d> approach) {
  return side_from(vote("circle3d", centres, approach, 0.0, [&](const Eigen::Vector3d& c) {
    return radial(c - fit.center, fit.normal);
  }));
}

Fit<MaterialSide> material_side(const Sphere& fit, std::span<const Eigen::Vector3d> centres,
                                std::span<const Eigen::Vector3d> approach) {
  return side_from(vote("sphere", centres, approach, 0.0,
                        [&](const Eigen::Vector3d& c) { return Eigen::Vector3d(c - fit.center); }));
}

Fit<MaterialSide> material_side(const Cylinder& fit, std::span<const Eigen::Vector3d> centres,
                                std::span<const Eigen::Vector3d> approach) {
  return side_from(vote("cylinder", centres, approach, 0.0, [&](const Eigen::Vector3d& c) {
    return radial(c - fit.point, fit.direction);
  }));
}

Fit<MaterialSide> material_side(const Cone& fit, std::span<const Eigen::Vector3d> centres,
                                std::span<const Eigen::Vector3d> approach) {
  const Eigen::Vector3d a = fit.direction.normalized();
  const double phi = fit.half_angle();
  return side_from(vote("cone", centres, approach, 0.0, [&](const Eigen::Vector3d& c) {
    const Eigen::Vector3d u = radial(c - fit.point, a);
    if (u.norm() == 0.0) return Eigen::Vector3d(Eigen::Vector3d::Zero());
    return Eigen::Vector3d(std::cos(phi) * u.normalized() - std::sin(phi) * a);
  }));
}

Fit<Plane> compensate(const Plane& centre_fit, std::span<const Eigen::Vector3d> centres,
                      std::span<const Eigen::Vector3d> approach, double tip_radius) {
  const Eigen::Vector3d n = centre_fit.normal.normalized();
  auto v = vote("plane", centres, approach, tip_radius, [&](const Eigen::Vector3d&) { return n; });
  if (!v) return v.error();
  Plane out = centre_fit;
  // Probe moved along +n: the material is on the +n side, so the outward normal is -n.
  out.normal = *v > 0 ? Eigen::Vector3d(-n) : n;
  out.point = centre_fit.point - tip_radius * out.normal;
  if (*v > 0) {
    out.stats.min_residual = -centre_fit.stats.max_residual;
    out.stats.max_residual = -centre_fit.stats.min_residual;
  }
  return out;
}

Fit<Circle2> compensate(const Circle2& centre_fit, std::span<const Eigen::Vector2d> centres,
                        std::span<const Eigen::Vector2d> approach, double tip_radius) {
  const auto c3 = lift(centres);
  const auto a3 = lift(approach);
  const Eigen::Vector3d centre(centre_fit.center.x(), centre_fit.center.y(), 0.0);
  auto side = side_from(vote("circle2d", c3, a3, tip_radius,
                             [&](const Eigen::Vector3d& c) { return Eigen::Vector3d(c - centre); }));
  if (!side) return side.error();
  auto r = offset_radius("circle2d", centre_fit.radius(), *side, tip_radius);
  if (!r) return r.error();
  Circle2 out = centre_fit;
  out.diameter = 2.0 * *r;
  return out;
}

Fit<Circle3> compensate(const Circle3& centre_fit, std::span<const Eigen::Vector3d> centres,
                        std::span<const Eigen::Vector3d> approach, double tip_radius) {
  if (auto e = check_hits("circle3d", centres.size(), approach, tip_radius)) return *e;
  auto side = material_side(centre_fit, centres, approach);
  if (!side) return side.error();
  auto r = offset_radius("circle3d", centre_fit.radius(), *side, tip_radius);
  if (!r) return r.error();
  Circle3 out = centre_fit;
  out.diameter = 2.0 * *r;
  return out;
}

Fit<Sphere> compensate(const Sphere& centre_fit, std::span<const Eigen::Vector3d> centres,
                       std::span<const Eigen::Vector3d> approach, double tip_radius) {
  if (auto e = check_hits("sphere", centres.size(), approach, tip_radius)) return *e;
  auto side = material_side(centre_fit, centres, approach);
  if (!side) return side.error();
  auto r = offset_radius("sphere", centre_fit.radius(), *side, tip_radius);
  if (!r) return r.error();
  Sphere out = centre_fit;
  out.diameter = 2.0 * *r;
  return out;
}

Fit<Cylinder> compensate(const Cylinder& centre_fit, std::span<const Eigen::Vector3d> centres,
                         std::span<const Eigen::Vector3d> approach, double tip_radius) {
  if (auto e = check_hits("cylinder", centres.size(), approach, tip_radius)) return *e;
  auto side = material_side(centre_fit, centres, approach);
  if (!side) return side.error();
  auto r = offset_radius("cylinder", centre_fit.radius(), *side, tip_radius);
  if (!r) return r.error();
  Cylinder out = centre_fit;
  out.diameter = 2.0 * *r;
  return out;
}

Fit<Cone> compensate(const Cone& centre_fit, std::span<const Eigen::Vector3d> centres,
                     std::span<const Eigen::Vector3d> approach, double tip_radius) {
  if (auto e = check_hits("cone", centres.size(), approach, tip_radius)) return *e;
  auto side = material_side(centre_fit, centres, approach);
  if (!side) return side.error();
  Cone out = centre_fit;
  out.distance = *side == MaterialSide::Inner ? centre_fit.distance + tip_radius
                                              : centre_fit.distance - tip_radius;
  if (!(out.distance > 0.0)) {
    std::ostringstream os;
    os << "the compensated cone has no positive radius at its axis point (distance " << out.distance
       << ")";
    return detail::make_error(FitErrorCode::NonPositiveSize, "cone", os.str());
  }
  return out;
}

Fit<Plane> fit_plane_probed(std::span<const Eigen::Vector3d> centres,
                            std::span<const Eigen::Vector3d> approach, double tip_radius) {
  auto f = fit_plane(centres);
  if (!f) return f.error();
  return compensate(*f, centres, approach, tip_radius);
}

Fit<Circle2> fit_circle2d_probed(std::span<const Eigen::Vector2d> centres,
                                 std::span<const Eigen::Vector2d> approach, double tip_radius,
                                 const FitOptions& options) {
  auto f = fit_circle2d(centres, options);
  if (!f) return f.error();
  return compensate(*f, centres, approach, tip_radius);
}

Fit<Circle3> fit_circle3d_probed(std::span<const Eigen::Vector3d> centres,
                                 std::span<const Eigen::Vector3d> approach, double tip_radius,
                                 const FitOptions& options) {
  auto f = fit_circle3d(centres, options);
  if (!f) return f.error();
  return compensate(*f, centres, approach, tip_radius);
}

Fit<Sphere> fit_sphere_probed(std::span<const Eigen::Vector3d> centres,
                              std::span<const Eigen::Vector3d> approach, double tip_radius,
                              const FitOptions& options) {
  auto f = fit_sphere(centres, options);
  if (!f) return f.error();
  return compensate(*f, centres, approach, tip_radius);
}

Fit<Cylinder> fit_cylinder_probed(std::span<const Eigen::Vector3d> centres,
                                  std::span<const Eigen::Vector3d> approach, double tip_radius,
                                  const FitOptions& options) {
  auto f = fit_cylinder(centres, options);
  if (!f) return f.error();
  return compensate(*f, centres, approach, tip_radius);
}

Fit<Cone> fit_cone_probed(std::span<const Eigen::Vector3d> centres,
                          std::span<const Eigen::Vector3d> approach, double tip_radius,
                          const FitOptions& options) {
  auto f = fit_cone(centres, options);
  if (!f) return f.error();
  return compensate(*f, centres, approach, tip_radius);
}

}  // namespace imess::metrology
