// ScanControl on an unknown contour (ScanPhase::Contour): steering along the surface in its
// constraint, the stop body, the end (scan_control.hpp).
#include "imess/core/scan_control.hpp"

#include <algorithm>
#include <cmath>

namespace imess::core {

namespace {
// The slowest advance off the band (a fraction of the path speed), and how far a sphere's
// distance must grow past its least before the scan ends there, mm.
constexpr double kContourSlowest = 0.2;
constexpr double kClosestMargin = 1e-3;
// After braking at the end, the machine follows the last setpoint this long (plus twice the lead), s.
constexpr double kEndSettleBase = 0.02;
// The normal's rate of turn is smoothed over this, s; the deflection is this old when read
// (beyond the setpoint lead: a streamed card's status period), s.
constexpr double kTurnFilter = 0.01;
constexpr double kSampleAge = 0.01;

Vec3 contour_vec(const std::array<double, 3>& a) noexcept { return {a[0], a[1], a[2]}; }
}  // namespace

void ScanControl::begin_contour(const planner::PlannedSegment& seg) noexcept {
  const auto& k = seg.scan.contour;
  AxisVec start = AxisVec::Zero();
  for (int a = 0; a < loop_.n; ++a) start[a] = seg.start[a];
  c_ = loop_.cartesian(start) + e_;  // where the Approach left the setpoint
  origin_ = c_;
  t_ = contour_vec(k.direction);
  if (k.constraint == planner::ContourConstraint::Cylinder) {
    const Vec3 axis = contour_vec(k.axis);
    Vec3 rho = c_ - contour_vec(k.axis_point);
    rho -= axis * rho.dot(axis);
    radius_ = rho.norm();
  }
  contour_s_ = 0;
  meetings_ = side_ = 0;
  closing_ = finished_ = ending_ = ran_out_ = false;
  closest_ = 0;
  speed_ = held_s_ = 0;
  touched_ = false;
  turn_rate_ = Vec3::Zero();
  have_turn_ = false;
  end_normal_ = contour_vec(k.end_normal);
  end_clearance_ = k.clearance;
  have_point_ = false;
  travelled_ = 0;
  lost_s_ = 0;
}

double ScanControl::steer(const planner::ScanSpec& spec, bool contact, double target, double accel, double dt, double tau,
                          double lag, double error, hal::Setpoint& sp) noexcept {
  const auto& k = spec.contour;
  // The tangent in the constraint, orthogonal to the measured normal, continuing the last.
  Vec3 t;
  Vec3 axis = Vec3::UnitZ(), rho_hat = Vec3::UnitX();
  // The normal as it will be where the machine is when this setpoint runs: the measured one
  // turned on by its rate of turn over the lag (round an edge the measured normal lags behind).
  Vec3 n = n_hat_ + turn_rate_.cross(n_hat_) * lag;
  n = n.norm() > 1e-9 ? Vec3(n.normalized()) : n_hat_;
  if (k.constraint == planner::ContourConstraint::Plane) {
    t = contour_vec(k.plane_normal).cross(n);
  } else {
    axis = contour_vec(k.axis);
    Vec3 rho = c_ - contour_vec(k.axis_point);
    rho -= axis * rho.dot(axis);
    if (rho.norm() > 1e-9) rho_hat = rho.normalized();
    t = rho_hat.cross(n);
    if (!(t.norm() > 0.05)) t = t_ - rho_hat * t_.dot(rho_hat);  // the surface is the cylinder here: on as before
  }
  if (!(t.norm() > 1e-9)) t = t_;
  t.normalize();
  if (t.dot(t_) < 0) t = -t;
  t_ = t;
  // Slower off the band, not at all out of contact; the speed changes within the path's
  // acceleration.
  double scale = contact ? 1.0 : 0.0;
  if (const double off = std::fabs(error) - spec.band / 2; contact && off > 0)
    scale = std::max(kContourSlowest, 1 - (1 - kContourSlowest) * off / (spec.band / 2));
  speed_ = std::clamp(scale * target, speed_ - accel * dt, speed_ + accel * dt);
  if (!contact) speed_ = 0;  // off the surface: no step along a tangent that is not there
  Vec3 push = error * n_hat_ * std::min(1.0, dt / tau);
  const double most = kMaxCorrectionRate * dt;
  if (push.norm() > most) push *= most / push.norm();
  const Vec3 before = c_;
  const double advance = speed_ * dt;
  c_ += advance * t + push;
  if (k.constraint == planner::ContourConstraint::Plane) {
    const Vec3 pn = contour_vec(k.plane_normal);
    c_ -= pn * (c_ - origin_).dot(pn);
  } else {
    const Vec3 ap = contour_vec(k.axis_point);
    const Vec3 along = axis * (c_ - ap).dot(axis);
    Vec3 rho = c_ - ap - along;
    if (rho.norm() > 1e-9) c_ = ap + along + rho.normalized() * radius_;
  }
  contour_s_ += advance;
  const Vec3 velocity = (c_ - before) / std::max(dt, 1e-6);
  for (int c = 0; c < 3; ++c)
    if (const int a = loop_.config.layout.cartesian_axis(c); a >= 0) {
      double p = c_[c];
      if (loop_.referenced) p = std::clamp(p, loop_.config.axes[a].travel_min, loop_.config.axes[a].travel_max);
      sp.position[a] = p;
      sp.velocity[a] = velocity[c];
    }
  return speed_;
}

// The measured surface point against the stop body: true at its count-th meeting (a sphere:
// where, after the count-th entry, the distance to its centre is least).
bool ScanControl::stop_body_met(const planner::ScanContour& k, const Vec3& surface) noexcept {
  const Vec3 p = contour_vec(k.stop_point), n = contour_vec(k.stop_normal);
  double dist = 0;
  int side = 0;
  switch (k.stop) {
    case planner::StopBody::Sphere:
      dist = (surface - p).norm();
      side = dist < k.stop_radius ? -1 : 1;
      break;
    case planner::StopBody::Plane: side = sign((surface - p).dot(n)); break;
    case planner::StopBody::Cylinder: {
      Vec3 rho = surface - p;
      rho -= n * rho.dot(n);
      side = rho.norm() < k.stop_radius ? -1 : 1;
      break;
    }
  }
  if (closing_) {
    if (side > 0 || dist > closest_ + kClosestMargin) return true;
    closest_ = std::min(closest_, dist);
    return false;
  }
  if (side == 0) return false;  // on the plane: not yet across it
  const int was = side_;
  side_ = side;
  if (was == 0 || was == side || contour_s_ < k.stop_after) return false;
  if (k.stop == planner::StopBody::Sphere && side > 0) return false;  // a sphere counts its entries
  if (++meetings_ < k.count) return false;
  if (k.stop != planner::StopBody::Sphere) return true;
  closing_ = true;
  closest_ = dist;
  return false;
}

bool ScanControl::contour_cycle(const planner::PlannedSegment& seg, double fraction, hal::Setpoint& sp, double dt, Nanos now,
                                double lead, double tau, FailReason& why) noexcept {
  const auto& spec = seg.scan;
  const auto& ms = loop_.ms;
  const Vec3 here = loop_.cartesian(ms.position);
  const Vec3 delta = ms.deflection;
  const double d = delta.norm();
  const bool contact = d >= kContact;
  lost_s_ = contact || !touched_ ? 0 : lost_s_ + dt;
  if (lost_s_ > kLostContactBase + 2 * lead) {
    why = FailReason::ScanLostContact;
    return false;
  }
  // The measured normal's rate of turn (rad/s about its axis), smoothed over the samples.
  if (contact) {
    if (have_turn_) {
      const Vec3 raw = n_last_.cross(n_hat_) / std::max(dt, 1e-6);
      turn_rate_ += (raw - turn_rate_) * std::min(1.0, dt / kTurnFilter);
    }
    n_last_ = n_hat_;
    have_turn_ = true;
  }
  const double lag = lead + kSampleAge;
  // Met its stop body: it brakes along the surface (in contact, at the segment's path
  // acceleration), holds until the machine has followed (the setpoint lead), then ends.
  const double accel = std::max(seg.a, 1.0);
  if (ending_) {
    if (steer(spec, contact, 0, accel, dt, tau, lag, d - spec.deflection, sp) == 0) held_s_ += dt;
    if (held_s_ < kEndSettleBase + 2 * lead) return true;
    finished_ = true;
    why = FailReason::PartNotFound;  // for ran_out()
    return false;
  }
  // Until the surface is first touched the correction alone seeks it along the start
  // normal, at most the clearance beyond the nominal start: else PartNotFound.
  if (!touched_) {
    touched_ = contact;
    if (!touched_ && (c_ - origin_).norm() > spec.contour.clearance) {
      why = FailReason::PartNotFound;
      return false;
    }
  }
  const Vec3 planned_velocity = loop_.cartesian(sp.velocity);
  const double speed = steer(spec, contact, planned_velocity.norm(), accel, dt, tau, lag, d - spec.deflection, sp);
  take_point(seg, here, delta, contact, now);
  if (contact && stop_body_met(spec.contour, here + delta - loop_.config.params.tip_radius * n_hat_)) {
    ending_ = true;
    held_s_ = 0;
  }
  // The planned length runs out before the stop body: it ends the same way (braking,
  // holding) just before the segment does, and fails.
  if (!ending_ && seg.duration() * (1 - fraction) <= speed / accel + kEndSettleBase + 2 * lead + 3 * dt) {
    ending_ = ran_out_ = true;
    held_s_ = 0;
  }
  return true;
}

}  // namespace imess::core
