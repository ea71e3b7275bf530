// A scan as planner requests: Position, Approach, Follow, Leave (scan.hpp).
#include "imess/planner/scan.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace imess::planner {
namespace {

using V3 = Eigen::Vector3d;

V3 vec(const Point3& p) { return {p[0], p[1], p[2]}; }
Point3 arr(const V3& v) { return {v.x(), v.y(), v.z()}; }

Pose at(Pose pose, const V3& p) {
  for (int a = 0; a < 3; ++a) pose[a] = p[a];
  return pose;
}

Line line(std::uint32_t id, const Pose& from, const V3& to, double feed, const ScanSpec& spec) {
  Line l;
  l.id = id;
  l.target = at(from, to);
  l.feed = feed;
  l.scan = spec;
  return l;
}

// The nominal surface's outward normal at surface point p of a circle or helix.
V3 circle_normal(const ScanCircleShape& c, const V3& axis, const V3& p) {
  V3 v = p - vec(c.centre);
  v -= axis * v.dot(axis);
  return c.radial * v.normalized() * std::sqrt(std::max(0.0, 1 - c.axial * c.axial)) + c.axial * axis;
}

struct Ends {
  V3 start, end, n_start, n_end;  // surface points and their normals
};

// A unit vector, or why not.
bool unit(const Point3& p, V3& out) {
  out = vec(p);
  if (!(out.norm() > 1e-9)) return false;
  out.normalize();
  return true;
}

// How far from p along unit u the line stays inside the travel box (0 when p is outside).
double within_travel(const V3& p, const V3& u, const ScanSettings& s) {
  double t = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (p[a] < s.travel_min[a] || p[a] > s.travel_max[a]) return 0;
    if (u[a] > 1e-12) t = std::min(t, (s.travel_max[a] - p[a]) / u[a]);
    if (u[a] < -1e-12) t = std::min(t, (s.travel_min[a] - p[a]) / u[a]);
  }
  return t;
}

// An unknown contour: Position and Approach as a line scan's, then one Contour segment from
// the ball centre's contact toward the direction point, as long as max_length and the travel
// allow (its profile is the contour's speed; the loop steers).
ScanRequests contour_requests(std::uint32_t id, const Pose& from, const ScanContourShape& c, const ScanSettings& s) {
  V3 n, t, pn, axis, stop_n, end_n;
  if (!unit(c.start_normal, n)) return std::string("the start's surface normal must not be zero");
  if (!unit(c.end_normal, end_n)) return std::string("the end normal (the back-off's direction) must not be zero");
  if (!(c.count >= 1)) return std::string("the stop body's count must be a whole number from 1");
  if (!(c.stop_after >= 0)) return std::string("the contour before the stop body counts must not be negative");
  if (!(c.max_length > 0)) return std::string("the contour's longest length must be above 0");
  const double offset = s.tip_radius - s.deflection;
  const V3 start = vec(c.start), ball = start + offset * n, to = vec(c.direction) - start;
  if (!(to.norm() >= 1e-3)) return std::string("the direction point must not be the start");
  ScanContour k;
  k.constraint = c.constraint;
  if (c.constraint == ContourConstraint::Plane) {
    if (!unit(c.plane_normal, pn)) return std::string("the scanning plane's normal must not be zero");
    t = pn.cross(n);
    if (!(t.norm() > 0.01)) return std::string("the scanning plane must not lie along the surface at the start (its normal along the start normal)");
    k.plane_normal = arr(pn);
  } else {
    if (!unit(c.axis, axis)) return std::string("the cylinder's axis must not be zero");
    V3 radial = ball - vec(c.axis_point);
    radial -= axis * radial.dot(axis);
    if (!(radial.norm() > 0.01)) return std::string("the start must lie off the cylinder's axis");
    t = radial.normalized().cross(n);
    if (!(t.norm() > 0.01)) t = to - radial.normalized() * to.dot(radial.normalized());  // the surface is the cylinder
    k.axis_point = c.axis_point;
    k.axis = arr(axis);
  }
  t -= n * t.dot(n);
  if (!(std::fabs(t.normalized().dot(to.normalized())) > 0.01))
    return std::string("the direction point must lie ahead along the contour, not straight across it");
  t = t.normalized() * (t.dot(to) > 0 ? 1 : -1);
  k.direction = arr(t);
  k.stop = c.stop;
  k.stop_point = c.stop_point;
  if (c.stop == StopBody::Sphere || c.stop == StopBody::Cylinder) {
    if (!(c.stop_diameter > 0)) return std::string("the stop body's diameter must be above 0");
    k.stop_radius = c.stop_diameter / 2;
  }
  if (c.stop != StopBody::Sphere) {
    if (!unit(c.stop_normal, stop_n))
      return std::string(c.stop == StopBody::Plane ? "the stop plane's normal must not be zero" : "the stop cylinder's axis must not be zero");
    k.stop_normal = arr(stop_n);
  }
  k.count = c.count;
  k.stop_after = c.stop_after;
  k.end_normal = arr(end_n);
  k.clearance = s.clearance;
  // The planned line: toward the direction point within the constraint, inside the travel.
  V3 u = to;
  if (c.constraint == ContourConstraint::Plane) u -= pn * u.dot(pn);
  if (!(u.norm() > 1e-6)) u = t;
  u.normalize();
  const double length = std::min(c.max_length, within_travel(ball, u, s) - 1e-3);
  if (!(length >= 1)) return std::string("the direction leads out of the travel within 1 mm of the start");
  ScanSpec spec;
  spec.deflection = s.deflection;
  spec.band = s.band;
  spec.step = s.step;
  spec.normal = arr(n);
  std::vector<Request> out;
  ScanSpec position;
  position.phase = ScanPhase::Position;
  out.push_back(line(id, from, ball + s.clearance * n, s.feed, position));
  spec.phase = ScanPhase::Approach;
  out.push_back(line(id, from, ball, s.approach_speed, spec));
  spec.phase = ScanPhase::Contour;
  spec.contour = k;
  out.push_back(line(id, from, ball + length * u, s.speed, spec));
  return out;
}

}  // namespace

ScanRequests scan_requests(std::uint32_t id, const Pose& from, const ScanShape& shape, const ScanSettings& s) {
  if (!(s.clearance > kMaxScanCorrection)) return std::string("the clearance must exceed the largest correction, 1 mm");
  if (const auto* c = std::get_if<ScanContourShape>(&shape)) return contour_requests(id, from, *c, s);
  const double offset = s.tip_radius - s.deflection;  // surface → ball centre, along the normal
  ScanSpec spec;
  spec.deflection = s.deflection;
  spec.band = s.band;
  spec.step = s.step;
  Ends e;
  std::variant<V3, Arc> follow;  // the ball centre's end of a line, or the arc
  if (const auto* l = std::get_if<ScanLineShape>(&shape)) {
    e.start = vec(l->start);
    e.end = vec(l->end);
    const V3 d = e.end - e.start;
    if (!(d.norm() >= 1e-3)) return std::string("the line must be at least 0.001 mm long");
    const V3 u = d.normalized();
    V3 n = vec(l->normal);
    if (!(n.norm() > 1e-9)) return std::string("the surface normal must not be zero");
    n.normalize();
    n -= u * n.dot(u);  // the normal across the line
    if (!(n.norm() > 0.1)) return std::string("the surface normal must not lie along the line");
    n.normalize();
    e.n_start = e.n_end = n;
    spec.normal = arr(n);
    follow = V3(e.end + offset * n);
  } else {
    const auto& c = std::get<ScanCircleShape>(shape);
    V3 axis = vec(c.axis);
    if (!(axis.norm() > 1e-9)) return std::string("the circle's axis must not be zero");
    axis.normalize();
    if (c.radial != 1 && c.radial != -1) return std::string("the surface must face away from the axis or toward it");
    if (!(std::fabs(c.axial) <= 1)) return std::string("the normal's part along the axis must lie between -1 and 1");
    if (!(std::fabs(c.sweep) >= 1e-3)) return std::string("the sweep must not be zero");
    e.start = vec(c.start);
    V3 radial = e.start - vec(c.centre);
    radial -= axis * radial.dot(axis);
    const double r_surface = radial.norm();
    if (!(r_surface >= 1e-3)) return std::string("the start must lie off the axis");
    const double r_ball = r_surface + c.radial * offset * std::sqrt(std::max(0.0, 1 - c.axial * c.axial));
    if (!(r_ball > 0.01)) {
      char why[160];
      std::snprintf(why, sizeof why, "the circle (radius %.4g mm) is too small for the tip (radius %.4g mm, deflected %.4g mm)",
                    r_surface, s.tip_radius, s.deflection);
      return std::string(why);
    }
    const double sweep = c.sweep * M_PI / 180;
    const Eigen::AngleAxisd turn(sweep, axis);
    e.end = vec(c.centre) + axis * (e.start - vec(c.centre)).dot(axis) + turn * radial + c.lead * axis;
    e.n_start = circle_normal(c, axis, e.start);
    e.n_end = circle_normal(c, axis, e.end);
    spec.centre = c.centre;
    spec.axis = arr(axis);
    spec.radial = static_cast<std::int8_t>(c.radial);
    spec.axial = c.axial;
    Arc a;
    a.id = id;
    a.centre = arr(vec(c.centre) + offset * c.axial * axis);
    a.normal = arr(axis);
    a.ccw = sweep > 0;
    a.turns = static_cast<int>(std::floor((std::fabs(c.sweep) - 1e-9) / 360));
    a.feed = s.speed;
    a.scan = spec;
    a.scan.phase = ScanPhase::Follow;
    a.target = at(from, e.end + offset * e.n_end);
    follow = a;
  }
  const V3 ball_start = e.start + offset * e.n_start, ball_end = e.end + offset * e.n_end;
  std::vector<Request> out;
  ScanSpec position;
  position.phase = ScanPhase::Position;
  out.push_back(line(id, from, ball_start + s.clearance * e.n_start, s.feed, position));
  spec.phase = ScanPhase::Approach;
  out.push_back(line(id, from, ball_start, s.approach_speed, spec));
  spec.phase = ScanPhase::Follow;
  if (const auto* end = std::get_if<V3>(&follow))
    out.push_back(line(id, from, *end, s.speed, spec));
  else
    out.push_back(std::get<Arc>(follow));
  spec.phase = ScanPhase::Leave;
  out.push_back(line(id, from, ball_end + s.clearance * e.n_end, s.approach_speed, spec));
  return out;
}

}  // namespace imess::planner
