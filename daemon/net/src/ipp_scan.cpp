// The I++ DME known-contour scans on the motion core's scan (planner/scan.hpp, docs/ippdme.md
// "Scanning"): ScanOnLine, ScanOnCircle, ScanOnHelix in the session's coordinate system become
// a scan in machine coordinates with the active tool's radius, ScanPar's speed and retract and
// the machine's deflection set-point; the points come back from the journal (scanned) and go
// out as data lines of the scan's tag, kScanPointsPerLine to a line, the rest before its `%`.
#include <algorithm>
#include <cmath>

#include "imess/ippdme/format.hpp"
#include "imess/net/ipp_server.hpp"

namespace imess::net {

using ippdme::ErrorCode;
using ippdme::Param;
using ippdme::Point3;

namespace {
Point3 from_vector(const ippdme::Vector3& v) { return {v.i, v.j, v.k}; }
double distance(const Point3& a, const Point3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }
}  // namespace

bool IppServer::start_scan(const Pending& p, const planner::ScanShape& shape, double step_mm) {
  const std::string_view name = ippdme::method_name(p.command);
  if (!tools_.active() || !tools_.active()->measures) {
    fail(p.tag, ErrorCode::ToolNotDefined, name);  // UnDefTool or NoTool: nothing measures
    return true;
  }
  if (!take_machine(p)) return true;
  planner::ScanSettings s = gateway_.scan_settings(tools_.act(Param::ScanSpeed));
  s.tip_radius = tools_.active()->radius;
  s.step = std::max(step_mm, 0.001);
  s.approach_speed = tools_.act(Param::PtMeasSpeed);
  s.feed = tools_.act(Param::GoToSpeed);
  s.clearance = std::max(tools_.act(Param::ScanRetract), 2.0);  // beyond the largest correction
  const std::uint32_t id = next_id();
  const auto requests = planner::scan_requests(id, gateway_.planned_end(), shape, s);
  if (const auto* why = std::get_if<std::string>(&requests)) {
    spdlog::info("I++ DME: {} refused: {}", name, *why);
    fail(p.tag, ErrorCode::BadArgument, name);
    return true;
  }
  auto list = std::get<std::vector<planner::Request>>(requests);
  for (auto& r : list)  // ScanPar.Accel when the client lowered it
    if (auto* l = std::get_if<planner::Line>(&r)) l->max_accel = tools_.lowered(Param::ScanAccel);
  std::string why;
  if (const auto planned = plan_requests(list, why); planned != Planned::Yes) {
    if (planned == Planned::Busy) return wait_for_rest();
    spdlog::info("I++ DME: {} refused: {}", name, why);
    fail(p.tag, refusal_error(planned), name);
    return true;
  }
  scan_points_.clear();
  step_ = Step::Scan;
  first_id_ = wait_id_ = id;
  return false;
}

bool IppServer::start_scan_line(const Pending& p, const ippdme::ScanOnLine& c) {
  planner::ScanLineShape line;
  line.start = csy_.to_machine(c.start);
  line.end = csy_.to_machine(c.end);
  line.normal = csy_.vector_to_machine(from_vector(c.normal));
  return start_scan(p, line, c.step);
}

// sfa: the surface normal at the start is cos(sfa)·x + sin(sfa)·z (x from the centre to the
// start, z the circle's normal): its part along the axis is sin(sfa), and it faces away from
// the axis when cos(sfa) ≥ 0. StepW is an angle: the points' spacing at the start's radius.
bool IppServer::start_scan_circle(const Pending& p, const Point3& centre, const Point3& start, const ippdme::Vector3& normal,
                                  double delta, double sfa, double step_deg, double pitch) {
  const double kDeg = M_PI / 180;
  planner::ScanCircleShape circle;
  circle.centre = csy_.to_machine(centre);
  circle.start = csy_.to_machine(start);
  circle.axis = csy_.vector_to_machine(from_vector(normal));
  circle.sweep = delta;
  circle.radial = std::cos(sfa * kDeg) >= -1e-12 ? 1 : -1;
  circle.axial = std::clamp(std::sin(sfa * kDeg), -1.0, 1.0);
  circle.lead = pitch * delta / 360;
  const double radius = distance(centre, start);
  return start_scan(p, circle, std::fabs(step_deg) * kDeg * radius);
}

void IppServer::scanned(const core::Event& e) {
  if (!conn_ || !in_session_ || step_ != Step::Scan || e.id != wait_id_ || queue_.empty()) return;
  ippdme::ScanPoint point;
  point.xyz = csy_.from_machine({e.p.x(), e.p.y(), e.p.z()});
  const Point3 n = csy_.vector_from_machine({-e.dir.x(), -e.dir.y(), -e.dir.z()});  // out of the material
  point.ijk = {n[0], n[1], n[2]};
  point.er = e.radius;
  scan_points_.push_back(point);
  if (scan_points_.size() >= ippdme::kScanPointsPerLine) flush_scan_points();
}

void IppServer::flush_scan_points() {
  if (scan_points_.empty() || queue_.empty() || !conn_) return;
  send(ippdme::format_scan_data(queue_.front().tag, scan_items_, scan_points_));
  scan_points_.clear();
}

}  // namespace imess::net

namespace imess::net {

namespace {
using ippdme::Vector3;
constexpr double kNoStop = 0;

// What the five unknown-contour methods have in common, in machine coordinates.
struct ContourIn {
  Point3 start{}, start_normal{}, direction{}, end_normal{};
  double step = 0;
  int count = 1;
};

template <class T>
ContourIn common(const T& c, const ippdme::CsyChain& csy) {
  return {csy.to_machine(c.start), csy.vector_to_machine(from_vector(c.start_normal)), csy.to_machine(c.direction),
          csy.vector_to_machine(from_vector(c.end_normal)), c.step, c.count};
}

void stop_at_sphere(planner::ScanContourShape& s, const Point3& centre, double diameter, const ippdme::CsyChain& csy) {
  s.stop = planner::StopBody::Sphere;
  s.stop_point = csy.to_machine(centre);
  s.stop_diameter = diameter;
  s.stop_after = kNoStop;
}
// A stop plane or cylinder counts once the scan has gone |direction − start| (docs/ippdme.md).
void stop_at_plane(planner::ScanContourShape& s, const Point3& point, const Vector3& normal, const ippdme::CsyChain& csy) {
  s.stop = planner::StopBody::Plane;
  s.stop_point = csy.to_machine(point);
  s.stop_normal = csy.vector_to_machine(from_vector(normal));
  s.stop_after = distance(s.start, s.direction);
}
void stop_at_cylinder(planner::ScanContourShape& s, const Point3& point, const Vector3& axis, double diameter,
                      const ippdme::CsyChain& csy) {
  s.stop = planner::StopBody::Cylinder;
  s.stop_point = csy.to_machine(point);
  s.stop_normal = csy.vector_to_machine(from_vector(axis));
  s.stop_diameter = diameter;
  s.stop_after = distance(s.start, s.direction);
}

template <class T>
planner::ScanContourShape contour_shape(const T& c, const ippdme::CsyChain& csy) {
  const ContourIn in = common(c, csy);
  planner::ScanContourShape s;
  s.start = in.start;
  s.start_normal = in.start_normal;
  s.direction = in.direction;
  s.end_normal = in.end_normal;
  s.count = in.count;
  if constexpr (std::is_same_v<T, ippdme::ScanInCylEndIsSphere> || std::is_same_v<T, ippdme::ScanInCylEndIsPlane>) {
    s.constraint = planner::ContourConstraint::Cylinder;
    s.axis_point = csy.to_machine(c.axis_point);
    s.axis = csy.vector_to_machine(from_vector(c.axis));
  } else {
    s.constraint = planner::ContourConstraint::Plane;
    s.plane_normal = csy.vector_to_machine(from_vector(ippdme::scan_plane_normal(c)));
  }
  if constexpr (std::is_same_v<T, ippdme::ScanInPlaneEndIsSphere> || std::is_same_v<T, ippdme::ScanInCylEndIsSphere>)
    stop_at_sphere(s, c.end_center, c.diameter, csy);
  else if constexpr (std::is_same_v<T, ippdme::ScanInPlaneEndIsCyl>)
    stop_at_cylinder(s, c.axis_point, c.axis, c.diameter, csy);
  else
    stop_at_plane(s, c.stop_point, c.stop_normal, csy);
  return s;
}
}  // namespace

// StepW 0: ScanUnknownDensity's Dis, else the machine's ScanStep.
template <class T>
bool IppServer::start_contour(const Pending& p, const T& c) {
  const double step = c.step > 0 ? c.step : unknown_density_.value_or(gateway_.params().scan_step);
  return start_scan(p, contour_shape(c, csy_), step);
}

template bool IppServer::start_contour(const Pending&, const ippdme::ScanInPlaneEndIsSphere&);
template bool IppServer::start_contour(const Pending&, const ippdme::ScanInPlaneEndIsPlane&);
template bool IppServer::start_contour(const Pending&, const ippdme::ScanInPlaneEndIsCyl&);
template bool IppServer::start_contour(const Pending&, const ippdme::ScanInCylEndIsSphere&);
template bool IppServer::start_contour(const Pending&, const ippdme::ScanInCylEndIsPlane&);

}  // namespace imess::net
