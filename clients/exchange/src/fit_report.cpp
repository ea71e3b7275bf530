// fit_points(): one library fit per kind, flattened into a FitReport. line2d/circle2d find the
// coordinate plane the points lie in, fit there and embed the result again.
#include "imess/exchange/fit_report.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "imess/metrology/fit.hpp"
#include "imess/metrology/probe_compensation.hpp"

namespace imess::exchange {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using metrology::Fit;
using metrology::FitError;
using metrology::FitErrorCode;

struct KindName {
  FitKind kind;
  std::string_view name;
};
constexpr std::array<KindName, 8> kNames{{{FitKind::Line, "line"},
                                          {FitKind::Line2d, "line2d"},
                                          {FitKind::Plane, "plane"},
                                          {FitKind::Circle, "circle"},
                                          {FitKind::Circle2d, "circle2d"},
                                          {FitKind::Sphere, "sphere"},
                                          {FitKind::Cylinder, "cylinder"},
                                          {FitKind::Cone, "cone"}}};

void set_stats(FitReport& r, const metrology::FitStats& s) {
  r.rms = s.rms;
  r.form_min = s.min_residual;
  r.form_max = s.max_residual;
  r.n = s.point_count;
}

// The coordinate plane holding all points: index k of the constant coordinate and the two
// others (i, j) in right-handed order, so that e_i x e_j = e_k.
struct CoordinatePlane {
  int k, i, j;
};

Fit<CoordinatePlane> coordinate_plane(std::span<const Vector3d> points, std::string_view kind) {
  if (points.empty())
    return FitError{FitErrorCode::TooFewPoints, std::string(kind) + ": no points"};
  Vector3d lo = points[0], hi = points[0];
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vector3d spread = hi - lo;
  const double tolerance = 1e-9 * std::max(1.0, spread.maxCoeff());
  for (int k : {2, 1, 0}) {
    if (spread[k] <= tolerance) return CoordinatePlane{k, (k + 1) % 3, (k + 2) % 3};
  }
  char buf[200];
  std::snprintf(buf, sizeof buf, "the %zu points lie in no coordinate plane (spread x %.6g, y %.6g, z %.6g)",
                points.size(), spread.x(), spread.y(), spread.z());
  return FitError{FitErrorCode::InvalidArgument,
                  std::string(kind) + ": " + buf + "; one coordinate must be the same for all points (use '" +
                      (kind == "line2d" ? "line" : "circle") + "' for a feature in space)"};
}

std::vector<Vector2d> flatten(std::span<const Vector3d> points, const CoordinatePlane& cp) {
  std::vector<Vector2d> flat;
  flat.reserve(points.size());
  for (const auto& p : points) flat.emplace_back(p[cp.i], p[cp.j]);
  return flat;
}

Vector3d embed(const Vector2d& v, double k_value, const CoordinatePlane& cp) {
  Vector3d out;
  out[cp.i] = v.x();
  out[cp.j] = v.y();
  out[cp.k] = k_value;
  return out;
}

Fit<FitReport> fit_2d(FitKind kind, std::span<const Vector3d> points) {
  const std::string_view name = to_string(kind);
  auto plane = coordinate_plane(points, name);
  if (!plane) return plane.error();
  const CoordinatePlane cp = *plane;
  const double level = points[0][cp.k];
  const auto flat = flatten(points, cp);
  FitReport r;
  r.kind = kind;
  r.normal = Vector3d::Unit(cp.k);
  if (kind == FitKind::Line2d) {
    auto f = metrology::fit_line2d(flat);
    if (!f) return f.error();
    r.point = embed(f->point, level, cp);
    r.direction = embed(f->direction, 0.0, cp);
    set_stats(r, f->stats);
  } else {
    auto f = metrology::fit_circle2d(flat);
    if (!f) return f.error();
    r.center = embed(f->center, level, cp);
    r.diameter = f->diameter;
    set_stats(r, f->stats);
  }
  return r;
}

}  // namespace

FitKind parse_fit_kind(std::string_view word) {
  for (const auto& [kind, name] : kNames)
    if (name == word) return kind;
  throw FitKindError("unknown feature kind '" + std::string(word) + "'; accepted: " + std::string(kFitKinds));
}

std::string_view to_string(FitKind kind) {
  for (const auto& [k, name] : kNames)
    if (k == kind) return name;
  return "?";
}

namespace {

// One report per library feature (shared by the surface and the probed paths).
FitReport report(const metrology::Plane& f) {
  FitReport r;
  r.kind = FitKind::Plane;
  r.point = f.point;
  r.normal = f.normal;
  set_stats(r, f.stats);
  return r;
}
FitReport report(const metrology::Circle3& f) {
  FitReport r;
  r.kind = FitKind::Circle;
  r.center = f.center;
  r.normal = f.normal;
  r.diameter = f.diameter;
  set_stats(r, f.stats);
  return r;
}
FitReport report(const metrology::Sphere& f) {
  FitReport r;
  r.kind = FitKind::Sphere;
  r.center = f.center;
  r.diameter = f.diameter;
  set_stats(r, f.stats);
  return r;
}
FitReport report(const metrology::Cylinder& f) {
  FitReport r;
  r.kind = FitKind::Cylinder;
  r.point = f.point;
  r.axis = f.direction;
  r.diameter = f.diameter;
  set_stats(r, f.stats);
  return r;
}
FitReport report(const metrology::Cone& f) {
  FitReport r;
  r.kind = FitKind::Cone;
  const double r0 = f.radius_at(0.0);
  r.point = f.point;
  r.axis = f.direction;
  r.diameter = 2.0 * r0;
  r.apex = f.point - (r0 / std::tan(f.half_angle())) * f.direction;
  r.apex_angle_deg = f.apex_angle_deg();
  set_stats(r, f.stats);
  return r;
}

template <class F>
Fit<FitReport> reported(const Fit<F>& f) {
  if (!f) return f.error();
  return report(*f);
}

}  // namespace

Fit<FitReport> fit_points(FitKind kind, std::span<const Vector3d> points) {
  switch (kind) {
    case FitKind::Line2d:
    case FitKind::Circle2d:
      return fit_2d(kind, points);
    case FitKind::Line: {
      auto f = metrology::fit_line3d(points);
      if (!f) return f.error();
      FitReport r;
      r.kind = kind;
      r.point = f->point;
      r.direction = f->direction;
      set_stats(r, f->stats);
      return r;
    }
    case FitKind::Plane: return reported(metrology::fit_plane(points));
    case FitKind::Circle: return reported(metrology::fit_circle3d(points));
    case FitKind::Sphere: return reported(metrology::fit_sphere(points));
    case FitKind::Cylinder: return reported(metrology::fit_cylinder(points));
    case FitKind::Cone: return reported(metrology::fit_cone(points));
  }
  return FitError{FitErrorCode::InvalidArgument, "unknown feature kind"};
}

bool has_probed_fit(FitKind kind) {
  return kind == FitKind::Plane || kind == FitKind::Circle || kind == FitKind::Sphere ||
         kind == FitKind::Cylinder || kind == FitKind::Cone;
}

Fit<FitReport> fit_probed_points(FitKind kind, std::span<const metrology::ProbedPoint> hits) {
  const std::string name(to_string(kind));
  std::vector<Vector3d> centres;
  std::vector<Vector3d> approach;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (!hits[i].has_approach())
      return FitError{FitErrorCode::InvalidArgument,
                      name + ": hit " + std::to_string(i) + " has no approach direction (a forced point, 0 0 0); "
                      "probe compensation needs one for every hit (messcap fit --surface fits the surface points)"};
    if (hits[i].radius != hits[0].radius)
      return FitError{FitErrorCode::InvalidArgument,
                      name + ": hit " + std::to_string(i) + " has tip radius " + std::to_string(hits[i].radius) +
                          ", hit 0 " + std::to_string(hits[0].radius) + "; one feature is fitted with one tip"};
    centres.push_back(hits[i].centre());
    approach.push_back(hits[i].approach);
  }
  const double r = hits.empty() ? 0.0 : hits[0].radius;
  switch (kind) {
    case FitKind::Plane: return reported(metrology::fit_plane_probed(centres, approach, r));
    case FitKind::Circle: return reported(metrology::fit_circle3d_probed(centres, approach, r));
    case FitKind::Sphere: return reported(metrology::fit_sphere_probed(centres, approach, r));
    case FitKind::Cylinder: return reported(metrology::fit_cylinder_probed(centres, approach, r));
    case FitKind::Cone: return reported(metrology::fit_cone_probed(centres, approach, r));
    default: break;
  }
  std::vector<Vector3d> surface;
  for (const auto& h : hits) surface.push_back(h.surface);
  return fit_points(kind, surface);
}

}  // namespace imess::exchange
