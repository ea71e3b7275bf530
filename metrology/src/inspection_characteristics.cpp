// Size, position, distance, angle, form and orientation of fitted features against their
// nominals. Nominal values of size, distance and angle come from the same definitions applied
// to the nominal geometry, unless the plan gives one.
#include "inspection_characteristics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "imess/metrology/compare.hpp"

namespace imess::metrology::detail {
namespace {

using Eigen::Vector3d;
using C = CharacteristicKind;
using F = FeatureKind;

enum class Locus { Point, Plane, Axis };

Locus locus(F k) {
  switch (k) {
    case F::Plane: return Locus::Plane;
    case F::Line:
    case F::Cylinder:
    case F::Cone: return Locus::Axis;
    default: return Locus::Point;
  }
}

double deg(double rad) { return rad * 180.0 / M_PI; }

// Distance between the loci of two features (point, plane or axis).
double distance_between(const Geometry& a, const Geometry& b) {
  const Locus la = locus(a.kind), lb = locus(b.kind);
  auto plane_gap = [](const Geometry& plane, const Vector3d& p) { return std::abs((p - plane.point).dot(plane.direction)); };
  if (la == Locus::Plane && lb == Locus::Plane) return 0.5 * (plane_gap(a, b.point) + plane_gap(b, a.point));
  if (la == Locus::Plane) return plane_gap(a, b.point);
  if (lb == Locus::Plane) return plane_gap(b, a.point);
  if (la == Locus::Axis && lb == Locus::Axis)
    return 0.5 * (point_line_distance(a.point, b.point, b.direction) + point_line_distance(b.point, a.point, a.direction));
  if (la == Locus::Axis) return point_line_distance(b.point, a.point, a.direction);
  if (lb == Locus::Axis) return point_line_distance(a.point, b.point, b.direction);
  return (a.point - b.point).norm();
}

double size_of(const Geometry& g, const Geometry& nominal, bool radius) {
  double d = g.diameter;
  if (g.kind == F::Cone) {  // the cross-section level with the nominal's axis point
    const double h = (nominal.point - g.point).dot(g.direction);
    d += 2 * h * std::tan(0.5 * g.apex_angle_deg * M_PI / 180.0);
  }
  return radius ? 0.5 * d : d;
}

// Width of the zone of orientation `c` of the feature to the datum direction. Planes: the
// range of their surface points across two parallel planes of the ideal orientation; axes:
// the axis over its measured extent, in a cylinder (parallel to the datum axis, perpendicular
// to a datum plane) or between two planes.
double orientation_zone(C c, const FeatureResult& f, const Geometry& datum) {
  const Geometry& g = *f.actual;
  const Vector3d a = datum.direction.normalized();
  const bool datum_is_plane = datum.kind == F::Plane;
  auto range_along = [](const std::vector<Vector3d>& pts, const Vector3d& n) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : pts) {
      lo = std::min(lo, p.dot(n));
      hi = std::max(hi, p.dot(n));
    }
    return hi - lo;
  };
  auto across = [](const Vector3d& v, const Vector3d& n) { return Vector3d(v - v.dot(n) * n); };
  if (g.kind == F::Plane) {
    // The ideal normal: the datum's (parallel to a datum plane / perpendicular to a datum axis),
    // or the feature's normal turned until it is square to the datum direction.
    const bool normal_is_datum = (c == C::Parallelism) == datum_is_plane;
    const Vector3d n = normal_is_datum ? a : across(g.direction, a).normalized();
    return range_along(f.surface, n);
  }
  const auto& ends = *f.axis_ends;
  const Vector3d span = ends[1] - ends[0];
  // Axis parallel to a datum plane / perpendicular to a datum axis: between two planes.
  const bool between_planes = (c == C::Parallelism) == datum_is_plane;
  if (between_planes) return std::abs(span.dot(a));
  return across(span, a).norm();  // the smallest cylinder along a holding the segment
}

}  // namespace

CharacteristicResult evaluate_characteristic(const Characteristic& c, const InspectionPlan& plan,
                                             const std::vector<FeatureResult>& fitted) {
  CharacteristicResult out;
  out.spec = c;
  auto result_of = [&](const std::string& name) -> const FeatureResult& {
    for (std::size_t i = 0; i < plan.features.size(); ++i)
      if (plan.features[i].name == name) return fitted[i];
    throw std::out_of_range("no feature named '" + name + "'");
  };
  const PlanFeature& pf = plan.feature(c.feature);
  const FeatureResult& fr = result_of(c.feature);
  const PlanFeature* po = c.other.empty() ? nullptr : &plan.feature(c.other);
  const FeatureResult* orr = c.other.empty() ? nullptr : &result_of(c.other);
  for (const FeatureResult* r : {&fr, orr}) {
    if (r && !r->actual) {
      out.error = "feature '" + r->name + "' has no fit: " + r->error;
      return out;
    }
  }
  const Geometry& g = *fr.actual;
  const Geometry& n = pf.nominal;
  switch (c.kind) {
    case C::Size:
      out.nominal = c.nominal.value_or(size_of(n, n, c.radius));
      out.actual = size_of(g, n, c.radius);
      break;
    case C::Distance:
      out.nominal = c.nominal.value_or(distance_between(n, po->nominal));
      out.actual = distance_between(g, *orr->actual);
      break;
    case C::Angle:
      out.nominal = c.nominal.value_or(deg(direction_angle(n.direction, po->nominal.direction)));
      out.actual = deg(direction_angle(g.direction, orr->actual->direction));
      break;
    case C::Position: {
      out.nominal_location = n.point;
      out.actual_location = g.point;
      const Vector3d d = g.point - n.point;
      switch (n.kind) {
        case F::Point: out.actual = 2 * std::abs(d.dot(n.direction)); break;
        case F::Circle: out.actual = 2 * (d - d.dot(n.direction) * n.direction).norm(); break;
        case F::Sphere: out.actual = 2 * d.norm(); break;
        default: {  // an axis: its worst end over the measured extent
          const auto& ends = *fr.axis_ends;
          out.actual = 2 * std::max(point_line_distance(ends[0], n.point, n.direction),
                                    point_line_distance(ends[1], n.point, n.direction));
          out.actual_location = 0.5 * (ends[0] + ends[1]);
        }
      }
      break;
    }
    case C::Flatness:
    case C::Roundness:
    case C::Cylindricity:
    case C::Sphericity: out.actual = fr.stats.form(); break;
    case C::Perpendicularity:
    case C::Parallelism: out.actual = orientation_zone(c.kind, fr, *orr->actual); break;
  }
  out.deviation = out.actual - out.nominal;
  out.in_tolerance = out.deviation >= c.lower && out.deviation <= c.upper;
  return out;
}

}  // namespace imess::metrology::detail
