// The planner: validation, per-segment limits (axes, feed rule, centripetal, minimum
// duration), junction deviation with Klipper's cap, look-ahead in v² and release of final
// segments (grbl's planned pointer, Klipper's lazy flush).
#include "imess/planner/planner.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace imess::planner {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
constexpr double kTravelSlack = 1e-9;   // mm or deg: rounding at a travel end
constexpr double kZeroLength = 1e-12;   // a move shorter than this does not move
// Share of the acceleration an arc keeps tangential; the rest, √(1 − 0.5²) ≈ 0.87, is
// left for the centripetal part (LinuxCNC tc.c), so |a| ≤ a_max on every axis.
constexpr double kArcTangential = 0.5;
const double kArcNormal = std::sqrt(1 - kArcTangential * kArcTangential);

Pose unit(const Pose& d) {
  double n = 0;
  for (double x : d) n += x * x;
  n = std::sqrt(n);
  Pose u{};
  if (n > 0)
    for (int i = 0; i < kMaxAxes; ++i) u[i] = d[i] / n;
  return u;
}

double dot(const Pose& a, const Pose& b) {
  double s = 0;
  for (int i = 0; i < kMaxAxes; ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

std::string describe(const AppendResult& r, const Machine& m) {
  const std::string seg = "segment " + std::to_string(r.id) + ": ";
  switch (r.error) {
    case PlanError::None: return seg + "accepted";
    case PlanError::OutOfTravel: {
      const char letter = r.axis >= 0 && r.axis < m.count ? m.axes[r.axis].letter : '?';
      return seg + "axis " + letter + " leaves its travel at " + std::to_string(r.value);
    }
    case PlanError::BadFeed:
      return seg + (r.value > 0 ? "feed must be a number of at least " + std::to_string(r.value)
                                : std::string("feed must be a number > 0"));
    case PlanError::BadPose: return seg + "target (and an arc's centre) must be a finite number on every axis";
    case PlanError::BadDwell: return seg + "a dwell or an output's hold must be a number of seconds >= 0";
    case PlanError::ArcBadPlane: return seg + "arc plane must be three distinct linear axes of the machine";
    case PlanError::ArcRadiusMismatch:
      return seg + "arc end is not on the circle: its radius differs from the start's by " + std::to_string(r.value) +
             " (accepted: up to " + std::to_string(r.limit) + ")";
    case PlanError::ArcDegenerate: return seg + "arc centre lies on the start point: the radius must be > 0";
    case PlanError::ArcZeroNormal: return seg + "arc plane normal must be a finite non-zero vector";
    case PlanError::ArcOffPlane:
      return seg + "arc end is " + std::to_string(r.value) + " off the plane through the start (accepted: up to " +
             std::to_string(r.limit) + "; a planar arc has no helix)";
    case PlanError::ArcBadTurns: return seg + "arc extra turns must be 0 or more";
    case PlanError::ProbeNoDirection:
      return seg + "probe target must lie at least 0.001 mm from where the probe starts (it gives the direction)";
    case PlanError::BadScan: return seg + "the scan's shape makes no scan";
  }
  return seg + "refused";
}

Planner::Planner(const Machine& machine, const PlannerOptions& options) : machine_(machine), options_(options) {
  validate(machine_);
  if (!(options_.junction_deviation >= 0) || !(options_.square_corner_velocity >= 0))
    throw std::invalid_argument("planner: junction_deviation and square_corner_velocity must be >= 0");
  if (!(options_.loop_period > 0)) throw std::invalid_argument("planner: loop_period must be > 0");
  if (!(options_.min_segment_periods >= 1)) throw std::invalid_argument("planner: min_segment_periods must be >= 1");
  if (!(options_.arc_tolerance > 0)) throw std::invalid_argument("planner: arc_tolerance must be > 0");
  for (int i = 0; i < machine_.count; ++i)  // a rotary U V W (the MRM arm's U1 U2) feeds in deg/s with A B C
    group_[i] = machine_.axes[i].kind == AxisKind::Rotary ? AxisGroup::Rotary : group_of(machine_.axes[i].letter);
}

void Planner::set_position(const Pose& pose) {
  pending_.clear();
  ready_.clear();
  have_last_final_ = false;
  position_ = Pose{};
  for (int i = 0; i < machine_.count; ++i) position_[i] = pose[i];
}

AppendResult Planner::check_travel(std::uint32_t id, const Pose& p) const {
  for (int i = 0; i < machine_.count; ++i) {
    const Axis& a = machine_.axes[i];
    if (p[i] < a.travel_min - kTravelSlack || p[i] > a.travel_max + kTravelSlack)
      return {PlanError::OutOfTravel, id, static_cast<std::int8_t>(i), p[i]};
  }
  return {PlanError::None, id};
}

AppendResult Planner::append(const Request& request) {
  if (const auto* l = std::get_if<Line>(&request)) return queue_line(*l);
  if (const auto* a = std::get_if<Arc>(&request)) return queue_arc(*a);
  PlannedSegment seg;
  seg.start = seg.end = position_;
  if (const auto* d = std::get_if<Dwell>(&request)) {
    if (!(d->seconds >= 0) || !std::isfinite(d->seconds)) return {PlanError::BadDwell, d->id};
    seg.id = d->id;
    seg.kind = SegmentKind::Dwell;
    seg.t_cruise = d->seconds;
    seg.profile = rest_profile(d->seconds);
  } else {
    const auto& o = std::get<SetOutput>(request);
    if (!(o.hold >= 0) || !std::isfinite(o.hold)) return {PlanError::BadDwell, o.id};
    seg.id = o.id;
    seg.kind = SegmentKind::SetOutput;
    seg.output = o.output;
    seg.output_value = o.value;
    seg.t_cruise = o.hold;
    seg.profile = rest_profile(o.hold);
  }
  queue_rest(seg);
  return {PlanError::None, seg.id};
}

bool Planner::feed_ok(double feed) const noexcept {
  return feed > 0 && feed >= options_.min_feed && std::isfinite(feed);
}

AppendResult Planner::queue_line(const Line& l) {
  Pose target{};
  for (int i = 0; i < machine_.count; ++i) {
    if (!std::isfinite(l.target[i])) return {PlanError::BadPose, l.id, static_cast<std::int8_t>(i)};
    target[i] = l.target[i];
  }
  if (auto r = check_travel(l.id, target); !r.ok()) return r;
  Pose delta{};
  double norm2[3] = {0, 0, 0};
  for (int i = 0; i < machine_.count; ++i) {
    delta[i] = target[i] - position_[i];
    norm2[static_cast<int>(group_[i])] += delta[i] * delta[i];
  }
  // Feed rule: L over XYZ if any moves, else UVW, else ABC.
  AxisGroup g = AxisGroup::Primary;
  for (AxisGroup c : {AxisGroup::Primary, AxisGroup::Secondary, AxisGroup::Rotary}) {
    g = c;
    if (std::sqrt(norm2[static_cast<int>(c)]) > kZeroLength) break;
  }
  const double L = std::sqrt(norm2[static_cast<int>(g)]);
  PlannedSegment seg;
  seg.id = l.id;
  seg.kind = SegmentKind::Line;
  seg.probe = l.probe;
  seg.scan = l.scan;
  seg.start = position_;
  seg.end = target;
  if (!(L > kZeroLength)) {  // zero-length: no motion, completes with its id
    seg.profile = rest_profile(0);
    queue_rest(seg);
    return {PlanError::None, l.id};
  }
  if (!feed_ok(l.feed)) return {PlanError::BadFeed, l.id, -1, options_.min_feed};
  // Path limits from every moving axis: v ≤ v_i/|u_i|, a ≤ a_i/|u_i| (u_i = Δ_i / L).
  double v = l.feed, a = kInf;
  for (int i = 0; i < machine_.count; ++i) {
    const double u = std::fabs(delta[i]) / L;
    if (u <= 0) continue;
    v = std::min(v, machine_.axes[i].max_velocity / u);
    a = std::min(a, machine_.axes[i].max_accel / u);
  }
  if (l.max_accel > 0) a = std::min(a, l.max_accel);
  v = std::min(v, L / (options_.min_segment_periods * options_.loop_period));
  seg.length = L;
  seg.a = a;
  Entry e;
  e.seg = seg;
  e.v_nom2 = v * v;
  e.moves = true;
  e.path_group = g;
  e.dir_in = e.dir_out = unit(delta);
  push(e);
  return {PlanError::None, l.id};
}

AppendResult Planner::queue_arc(const Arc& arc) {
  using Eigen::Vector3d;
  Pose target{};
  for (int i = 0; i < machine_.count; ++i) {
    if (!std::isfinite(arc.target[i])) return {PlanError::BadPose, arc.id, static_cast<std::int8_t>(i)};
    target[i] = arc.target[i];
  }
  const auto& ax = arc.plane_axes;
  for (int k = 0; k < 3; ++k) {
    if (ax[k] < 0 || ax[k] >= machine_.count || machine_.axes[ax[k]].kind != AxisKind::Linear ||
        ax[k] == ax[(k + 1) % 3])
      return {PlanError::ArcBadPlane, arc.id, ax[k]};
  }
  Vector3d n(arc.normal[0], arc.normal[1], arc.normal[2]);
  Vector3d c(arc.centre[0], arc.centre[1], arc.centre[2]);
  if (!n.allFinite() || !(n.norm() > 1e-12)) return {PlanError::ArcZeroNormal, arc.id};
  if (!c.allFinite()) return {PlanError::BadPose, arc.id};
  if (arc.turns < 0) return {PlanError::ArcBadTurns, arc.id};
  if (!feed_ok(arc.feed)) return {PlanError::BadFeed, arc.id, -1, options_.min_feed};
  if (auto r = check_travel(arc.id, target); !r.ok()) return r;
  n.normalize();
  const Vector3d p0(position_[ax[0]], position_[ax[1]], position_[ax[2]]);
  const Vector3d p1(target[ax[0]], target[ax[1]], target[ax[2]]);
  c += n * (p0 - c).dot(n);  // the centre in the start's plane
  const Vector3d r0v = p0 - c;
  const double r0 = r0v.norm();
  if (!(r0 > 1e-9)) return {PlanError::ArcDegenerate, arc.id};
  const Vector3d e1 = r0v / r0, e2 = n.cross(e1);
  const Vector3d q = p1 - c;
  const double h = q.dot(n);
  const Vector3d r1v = q - h * n;
  const double r1 = r1v.norm();
  const double tolerance = std::max({options_.arc_tolerance, 1e-3 * r0, arc.radius_tolerance});
  if (arc.planar && std::fabs(h) > tolerance) return {PlanError::ArcOffPlane, arc.id, -1, std::fabs(h), tolerance};
  if (std::fabs(r1 - r0) > tolerance) return {PlanError::ArcRadiusMismatch, arc.id, -1, std::fabs(r1 - r0), tolerance};
  double phi = std::atan2(r1v.dot(e2), r1v.dot(e1));
  if (arc.ccw && phi <= 1e-12) phi += 2 * kPi;
  if (!arc.ccw && phi >= -1e-12) phi -= 2 * kPi;
  phi += (arc.ccw ? 2 : -2) * kPi * arc.turns;
  const double r = 0.5 * (r0 + r1);
  const double L = std::hypot(r * phi, h);

  PlannedSegment seg;
  seg.id = arc.id;
  seg.kind = SegmentKind::Arc;
  seg.scan = arc.scan;
  seg.start = position_;
  seg.end = target;
  seg.length = L;
  ArcGeometry& g = seg.arc;
  g.axes = ax;
  for (int k = 0; k < 3; ++k) g.centre[k] = c[k], g.e1[k] = e1[k], g.e2[k] = e2[k], g.n[k] = n[k];
  g.r0 = r0, g.r1 = r1, g.phi = phi, g.h = h;

  // Travel: the ends, and each plane axis at its extremes along the helix. Axis k follows
  // x(θ) = c_k + r·m·cos(θ − α) + n_k·h·θ/φ; dx/dθ = 0 where sin(θ − α) = n_k·h/(φ·r·m).
  Pose pose, d;
  for (int k = 0; k < 3; ++k) {
    const double m = std::hypot(e1[k], e2[k]);
    if (m < 1e-12) continue;
    const double alpha = std::atan2(e2[k], e1[k]);
    const double qk = n[k] * h / (phi * r * m);
    if (std::fabs(qk) > 1) continue;
    const double lo = std::min(0.0, phi), hi = std::max(0.0, phi);
    for (double base : {alpha + std::asin(qk), alpha + kPi - std::asin(qk)}) {
      double th = base - 2 * kPi * std::ceil((base - lo) / (2 * kPi));
      for (; th <= hi; th += 2 * kPi) {
        if (th < lo) continue;
        pose_at(seg, th / phi * L, pose, d);
        if (auto res = check_travel(arc.id, pose); !res.ok()) return res;
      }
    }
  }

  // Limits. Plane axes: |tangent_k| ≤ 1, so v ≤ their v_max; tangential a ≤ 0.5·a_min and
  // centripetal v²κ ≤ 0.87·a_min (κ = r/(r² + (h/φ)²), the helix' curvature), so every axis
  // stays within a_min. Other axes move linearly: u_k = |Δ_k|/L as for a line.
  double v = arc.feed, a_plane = kInf, a_other = kInf;
  for (int k = 0; k < 3; ++k) {
    v = std::min(v, machine_.axes[ax[k]].max_velocity);
    a_plane = std::min(a_plane, machine_.axes[ax[k]].max_accel);
  }
  for (int i = 0; i < machine_.count; ++i) {
    if (i == ax[0] || i == ax[1] || i == ax[2]) continue;
    const double u = std::fabs(target[i] - position_[i]) / L;
    if (u <= 0) continue;
    v = std::min(v, machine_.axes[i].max_velocity / u);
    a_other = std::min(a_other, machine_.axes[i].max_accel / u);
  }
  const double lead = h / phi;
  const double kappa = r / (r * r + lead * lead);
  v = std::min(v, std::sqrt(kArcNormal * a_plane / kappa));
  v = std::min(v, L / (options_.min_segment_periods * options_.loop_period));
  seg.a = std::min(kArcTangential * a_plane, a_other);

  Entry e;
  e.seg = seg;
  e.v_nom2 = v * v;
  e.moves = true;
  e.path_group = group_[ax[0]];
  pose_at(seg, 0, pose, d);
  e.dir_in = unit(d);
  pose_at(seg, L, pose, d);
  e.dir_out = unit(d);
  push(e);
  return {PlanError::None, arc.id};
}

void Planner::queue_rest(PlannedSegment seg) {
  Entry e;
  e.seg = seg;
  push(e);
}

void Planner::push(Entry e) {
  e.seg.start = position_;
  e.max_entry2 = 0;
  if (!pending_.empty() && e.moves && pending_.back().moves) {
    const Entry& prev = pending_.back();
    e.max_entry2 = std::min({junction_v2(prev, e), prev.v_nom2, e.v_nom2});
  }
  e.entry2 = e.max_entry2;
  if (pending_.empty()) e.entry2 = 0;  // the previous final segment ended at rest
  pending_.push_back(e);
  position_ = e.seg.end;
  recalculate();
  release_final(false);
}

// Junction deviation (grbl, Jeon 2011) with Klipper's cap: the virtual arc touches each move
// no further than its middle, v² ≤ ½·a·L·tan(θ/2). θ is the inner angle (180° = straight on).
double Planner::junction_v2(const Entry& prev, const Entry& next) const noexcept {
  if (prev.path_group != next.path_group) return 0;  // mm against degrees: stop between
  const double cos_theta = -dot(prev.dir_out, next.dir_in);
  if (cos_theta > 0.999999) return 0;      // full reversal
  if (cos_theta < -0.999999) return kInf;  // straight on
  const double sin_d2 = std::sqrt(std::max(0.5 * (1 - cos_theta), 0.0));
  const double cos_d2 = std::sqrt(std::max(0.5 * (1 + cos_theta), 0.0));
  const double r_jd = sin_d2 / (1 - sin_d2);
  const double a = std::min(prev.seg.a, next.seg.a);
  const double vsc = options_.square_corner_velocity;
  const double delta = vsc > 0 ? vsc * vsc * (std::sqrt(2.0) - 1) / a : options_.junction_deviation;
  const double quarter_tan = 0.25 * sin_d2 / cos_d2;
  const double cap = std::min(2 * prev.seg.a * prev.seg.length, 2 * next.seg.a * next.seg.length) * quarter_tan;
  return std::min(r_jd * delta * a, cap);
}

// Reverse pass from the tail (which ends at rest), then forward pass from the head, whose
// entry is fixed (rest, or the exit of the segment released before it). The same passes
// with the tail free to end at any speed give best2, the most any later request can lift
// an entry to.
void Planner::recalculate() {
  const std::size_t n = pending_.size();
  double next2 = 0, next_best2 = kInf;
  for (std::size_t i = n; i-- > 1;) {
    Entry& e = pending_[i];
    const double reach = 2 * e.seg.a * e.seg.length;
    e.entry2 = std::min(e.max_entry2, next2 + reach);
    e.best2 = std::min(e.max_entry2, next_best2 + reach);
    next2 = e.entry2;
    next_best2 = e.best2;
  }
  if (n > 0) pending_[0].best2 = pending_[0].entry2;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Entry& e = pending_[i];
    Entry& f = pending_[i + 1];
    const double reach = 2 * e.seg.a * e.seg.length;
    f.entry2 = std::min(f.entry2, e.entry2 + reach);
    f.best2 = std::min(f.best2, e.best2 + reach);
  }
}

// The head is final when its exit (the next entry) no longer depends on how the queue ends:
// planned with the tail at rest it is already as high as with the tail free (grbl's planned
// pointer, Klipper's lazy flush). More requests only move the plan between the two.
void Planner::release_final(bool all) {
  while (!pending_.empty()) {
    Entry& head = pending_.front();
    double exit2 = 0;
    if (pending_.size() > 1) {
      const Entry& next = pending_[1];
      if (!all && next.entry2 < next.best2 * (1 - 1e-12)) return;
      exit2 = next.entry2;
    } else if (!all) {
      return;
    }
    finish(head, exit2);
    pending_.pop_front();
  }
}

void Planner::finish(Entry& e, double exit2) {
  PlannedSegment& s = e.seg;
  if (e.moves) {
    const Trapezoid t = plan_trapezoid(s.length, std::sqrt(e.entry2), std::sqrt(e.v_nom2), std::sqrt(exit2), s.a);
    s.v0 = t.v0, s.vc = t.vc, s.v1 = t.v1;
    s.t_acc = t.t_acc, s.t_cruise = t.t_cruise, s.t_dec = t.t_dec;
    s.profile = trapezoid_profile(s.length, t);
  }
  ready_.push_back(s);
  last_final_ = e;
  have_last_final_ = true;
}

void Planner::flush() {
  recalculate();
  release_final(true);
}

bool Planner::take(PlannedSegment& out) {
  if (ready_.empty()) return false;
  out = ready_.front();
  ready_.pop_front();
  return true;
}

double Planner::ready_duration() const noexcept {
  double t = 0;
  for (const auto& s : ready_) t += s.duration();
  return t;
}

}  // namespace imess::planner
