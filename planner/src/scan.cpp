// A scan as planner requests: Position, Approach, Follow, Leave (scan.hpp).
#include "imess/planner/scan.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

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

}  // namespace

ScanRequests scan_requests(std::uint32_t id, const Pose& from, const ScanShape& shape, const ScanSettings& s) {
  if (!(s.clearance > kMaxScanCorrection)) return std::string("the clearance must exceed the largest correction, 1 mm");
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
