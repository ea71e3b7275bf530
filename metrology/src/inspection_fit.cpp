// Fits one plan feature to its points with the library's fits (fit.hpp, probe_compensation.hpp)
// and re-expresses the result as a Geometry oriented like the nominal.
#include "inspection_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Geometry>

#include "imess/metrology/features.hpp"
#include "imess/metrology/fit.hpp"
#include "imess/metrology/probe_compensation.hpp"

namespace imess::metrology::detail {
namespace {

using Eigen::Vector3d;

FitError feature_error(const std::string& name, FitErrorCode code, const std::string& why) {
  return FitError{code, "feature '" + name + "': " + why};
}

FitStats stats_of(const std::vector<double>& residuals) {
  FitStats s;
  s.point_count = residuals.size();
  if (residuals.empty()) return s;
  s.min_residual = *std::min_element(residuals.begin(), residuals.end());
  s.max_residual = *std::max_element(residuals.begin(), residuals.end());
  double ssq = 0;
  for (double r : residuals) ssq += r * r;
  s.rms = std::sqrt(ssq / static_cast<double>(residuals.size()));
  return s;
}

FitStats negated(FitStats s) {
  const double lo = s.min_residual;
  s.min_residual = -s.max_residual;
  s.max_residual = -lo;
  return s;
}

Vector3d aligned_with(const Vector3d& d, const Vector3d& reference) { return d.dot(reference) < 0 ? Vector3d(-d) : d; }

// Component of v perpendicular to the unit direction a.
Vector3d across(const Vector3d& v, const Vector3d& a) { return v - v.dot(a) * a; }

std::array<Vector3d, 2> axis_extent(const Vector3d& point, const Vector3d& dir, const std::vector<Vector3d>& pts) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& p : pts) {
    const double h = (p - point).dot(dir);
    lo = std::min(lo, h);
    hi = std::max(hi, h);
  }
  return {point + lo * dir, point + hi * dir};
}

// Ball centre moved by the tip radius toward the material, along the unit outward normal n:
// inner features have their material outside, so the surface lies beyond the centre.
Vector3d to_surface(const Vector3d& centre, const Vector3d& radial_out, double r, bool inner) {
  return centre + (inner ? r : -r) * radial_out;
}

template <class T>
Fit<FittedFeature> failed(const std::string& name, const Fit<T>& f) {
  return feature_error(name, f.error().code, f.error().message);
}

// A feature's points: as measured, and for hits the ball centres and approaches.
struct Sample {
  std::vector<Vector3d> points, centres, approach;
  bool probed = false;
  double r = 0.0;
  const std::vector<Vector3d>& fitted() const { return probed ? centres : points; }
};

// A round feature fitted to the ball centres and offset by the tip radius (compensate()); `inner`
// becomes the side the approaches show (it stays the nominal's for plain points or r = 0).
template <class F, class Size>
Fit<F> round_fit(const Sample& s, Fit<F> centre_fit, Size size, bool& inner) {
  if (!centre_fit || !s.probed) return centre_fit;
  auto comp = compensate(*centre_fit, s.centres, s.approach, s.r);
  if (comp && s.r > 0) inner = size(*comp) > size(*centre_fit);
  return comp;
}

// Surface points: each ball centre moved by the radius toward the material along the fitted
// feature's outward unit normal there (normal_at(centre)); plain points as they are.
template <class Normal>
std::vector<Vector3d> surface_points(const Sample& s, bool inner, Normal normal_at) {
  if (!s.probed) return s.points;
  std::vector<Vector3d> out;
  for (const auto& c : s.centres) out.push_back(to_surface(c, normal_at(c), s.r, inner));
  return out;
}

}  // namespace

Fit<FittedFeature> fit_feature(const std::string& name, const Geometry& nominal, const std::vector<FitInput>& inputs) {
  if (inputs.empty()) return feature_error(name, FitErrorCode::TooFewPoints, "no points were measured");
  const bool probed = inputs.front().approach.has_value();
  const double r = inputs.front().radius;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (inputs[i].approach.has_value() != probed)
      return feature_error(name, FitErrorCode::InvalidArgument,
                           "point " + std::to_string(i + 1) + (probed ? " has no approach direction" : " has an approach direction") +
                               " while point 1 " + (probed ? "has" : "has not") + "; a feature's points are all hits (with approach and radius) or all plain points");
    if (probed && std::abs(inputs[i].radius - r) > 1e-9)
      return feature_error(name, FitErrorCode::InvalidArgument,
                           "point " + std::to_string(i + 1) + " was taken with tip radius " + std::to_string(inputs[i].radius) +
                               ", point 1 with " + std::to_string(r) + "; one feature needs one tip");
  }
  Sample sample;
  sample.probed = probed;
  sample.r = r;
  for (const auto& in : inputs) {
    sample.points.push_back(in.point);
    if (probed) {
      sample.centres.push_back(in.point - in.radius * *in.approach);
      sample.approach.push_back(*in.approach);
    }
  }
  const auto& points = sample.points;
  const auto& centres = sample.centres;

  FittedFeature out;
  out.geometry = nominal;
  out.compensated = probed;
  Geometry& g = out.geometry;
  switch (nominal.kind) {
    case FeatureKind::Point: {
      Vector3d mean = Vector3d::Zero();
      for (const auto& p : points) mean += p;
      mean /= static_cast<double>(points.size());
      g.point = mean;
      std::vector<double> res;
      for (const auto& p : points) res.push_back((p - mean).dot(g.direction));
      out.stats = stats_of(res);
      out.surface = points;  // compensated along the approach, as measured
      out.compensated = false;
      break;
    }
    case FeatureKind::Line: {
      auto f = fit_line3d(points);
      if (!f) return failed(name, f);
      g.point = f->point;
      g.direction = aligned_with(f->direction, nominal.direction);
      out.stats = f->stats;
      out.surface = points;  // a line has no surface normal of its own: compensated along the approach
      out.compensated = false;
      out.axis_ends = axis_extent(g.point, g.direction, points);
      break;
    }
    case FeatureKind::Plane: {
      Fit<Plane> f = probed ? fit_plane_probed(centres, sample.approach, r) : fit_plane(points);
      if (!f) return failed(name, f);
      const Vector3d n_out = f->normal;  // probed: out of the material
      out.stats = f->stats;
      if (probed)
        for (const auto& c : centres) out.surface.push_back(c - r * n_out);
      else
        out.surface = points;
      g.point = f->point;
      g.direction = aligned_with(n_out, nominal.direction);
      if (g.direction.dot(n_out) < 0) out.stats = negated(out.stats);
      break;
    }
    case FeatureKind::Circle: {
      auto c = round_fit(sample, fit_circle3d(sample.fitted()), [](const Circle3& f) { return f.diameter; }, g.inner);
      if (!c) return failed(name, c);
      g.point = c->center;
      g.direction = aligned_with(c->normal, nominal.direction);
      g.diameter = c->diameter;
      out.stats = c->stats;
      out.surface = surface_points(sample, g.inner, [&](const Vector3d& p) { return across(p - g.point, g.direction).normalized(); });
      break;
    }
    case FeatureKind::Sphere: {
      auto f = round_fit(sample, fit_sphere(sample.fitted()), [](const Sphere& s) { return s.diameter; }, g.inner);
      if (!f) return failed(name, f);
      g.point = f->center;
      g.diameter = f->diameter;
      out.stats = f->stats;
      out.surface = surface_points(sample, g.inner, [&](const Vector3d& p) { return (p - g.point).normalized(); });
      break;
    }
    case FeatureKind::Cylinder: {
      Cylinder start;
      start.point = nominal.point;
      start.direction = nominal.direction;
      start.diameter = nominal.diameter;
      auto c = round_fit(sample, fit_cylinder(sample.fitted(), start), [](const Cylinder& f) { return f.diameter; }, g.inner);
      if (!c) return failed(name, c);
      g.point = c->point;
      g.direction = aligned_with(c->direction, nominal.direction);
      g.diameter = c->diameter;
      out.stats = c->stats;
      out.surface = surface_points(sample, g.inner, [&](const Vector3d& p) { return across(p - g.point, g.direction).normalized(); });
      out.axis_ends = axis_extent(g.point, g.direction, out.surface);
      break;
    }
    case FeatureKind::Cone: {
      const double half = 0.5 * nominal.apex_angle_deg * M_PI / 180.0;
      Cone start;
      start.point = nominal.point;
      start.direction = nominal.direction;
      start.apex_angle_rad = 2 * half;
      start.distance = 0.5 * nominal.diameter * std::cos(half);
      auto c = round_fit(sample, fit_cone(sample.fitted(), start), [](const Cone& f) { return f.distance; }, g.inner);
      if (!c) return failed(name, c);
      const double phi = c->half_angle();
      g.point = c->point;
      g.direction = c->direction;  // toward increasing radius: a physical sign
      g.diameter = 2 * c->distance / std::cos(phi);
      g.apex_angle_deg = c->apex_angle_deg();
      out.stats = c->stats;
      out.surface = surface_points(sample, g.inner, [&](const Vector3d& p) {
        return Vector3d(std::cos(phi) * across(p - g.point, g.direction).normalized() - std::sin(phi) * g.direction);
      });
      out.axis_ends = axis_extent(g.point, g.direction, out.surface);
      break;
    }
  }
  return out;
}

}  // namespace imess::metrology::detail
