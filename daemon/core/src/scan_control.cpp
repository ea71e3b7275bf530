// ScanControl: the deflection held at its set-point along the measured normal; scan points.
#include "imess/core/scan_control.hpp"

#include <algorithm>
#include <cmath>

namespace imess::core {

namespace {
constexpr double kMinTau = 0.03;           // s
}  // namespace

using planner::ScanPhase;

void ScanControl::reset() noexcept {
  e_ = e_leave_ = Vec3::Zero();
  have_point_ = false;
  travelled_ = 0;
  contact_phase_ = false;
  phase_ = ScanPhase::None;
  lost_s_ = 0;
  finished_ = closing_ = ending_ = ran_out_ = false;
  meetings_ = side_ = 0;
  contour_s_ = 0;
}

void ScanControl::take_point(const planner::PlannedSegment& seg, const Vec3& here, const Vec3& delta, bool contact,
                             Nanos now) noexcept {
  // The path travelled along the surface since the last point (the correction's motion
  // across it does not count), with the remainder carried: points come every `step` on
  // average, not every whole number of cycles' travel beyond it.
  if (have_point_) {
    const Vec3 moved = here - last_point_;
    travelled_ += (moved - n_hat_ * moved.dot(n_hat_)).norm();
  }
  last_point_ = here;
  if (!contact || (have_point_ && travelled_ < seg.scan.step)) return;
  travelled_ = have_point_ ? std::min(travelled_ - seg.scan.step, seg.scan.step) : 0.0;
  have_point_ = true;
  Event ev;
  ev.kind = EventKind::ScanPt;
  ev.id = seg.id;
  ev.p = here + delta - loop_.config.params.tip_radius * n_hat_;
  ev.dir = -n_hat_;
  ev.radius = loop_.config.params.tip_radius;
  ev.compensated = true;
  ev.time = now;
  loop_.emit(ev);
}

Vec3 ScanControl::nominal_normal(const planner::ScanSpec& spec, const Vec3& p) const noexcept {
  if (spec.radial == 0) return Vec3(spec.normal[0], spec.normal[1], spec.normal[2]);
  const Vec3 axis(spec.axis[0], spec.axis[1], spec.axis[2]);
  Vec3 v = p - Vec3(spec.centre[0], spec.centre[1], spec.centre[2]);
  v -= axis * v.dot(axis);
  const double len = v.norm();
  if (!(len > 1e-9)) return axis;
  return spec.radial * (v / len) * std::sqrt(std::max(0.0, 1 - spec.axial * spec.axial)) + spec.axial * axis;
}

bool ScanControl::apply(const planner::PlannedSegment* seg, double fraction, hal::Setpoint& sp, double dt, Nanos now,
                        FailReason& why) noexcept {
  const ScanPhase phase = seg ? seg->scan.phase : ScanPhase::None;
  if (phase == ScanPhase::None || phase == ScanPhase::Position) {
    if (phase_ != ScanPhase::None) reset();
    phase_ = phase;
    return true;
  }
  const auto& spec = seg->scan;
  const auto& ms = loop_.ms;
  if (phase != phase_) {  // a new phase of the scan
    if (phase == ScanPhase::Approach) {
      reset();
      if (!ms.deflection_valid) {
        why = FailReason::NoMeasuringProbe;
        return false;
      }
    }
    if (phase == ScanPhase::Leave) e_leave_ = e_;
    if (phase == ScanPhase::Contour) begin_contour(*seg);
    phase_ = phase;
  }
  contact_phase_ = true;
  const Vec3 here = loop_.cartesian(ms.position);
  const Vec3 delta = ms.deflection;
  const double d = delta.norm();
  const bool contact = d >= kContact;
  // Out of contact on an unknown contour the last measured normal stands (there is no nominal).
  if (contact) n_hat_ = delta / d;
  else if (phase != ScanPhase::Contour) n_hat_ = nominal_normal(spec, here);
  if (ms.probe_over_range && phase != ScanPhase::Leave) {
    why = FailReason::ScanOverRange;
    return false;
  }
  const double lead = loop_.hw.path_lead_s();
  const double tau = std::max(kMinTau, 3 * lead);
  if (phase == ScanPhase::Contour) return contour_cycle(*seg, fraction, sp, dt, now, lead, tau, why);
  const Vec3 before = e_;
  if (phase == ScanPhase::Leave) {
    e_ = e_leave_ * (1 - fraction);
  } else {
    double error = d - spec.deflection;  // > 0: pressed too far, back off along n̂
    if (phase == ScanPhase::Approach) error = std::max(0.0, error);
    Vec3 step = error * n_hat_ * std::min(1.0, dt / tau);
    const double most = kMaxCorrectionRate * dt;
    if (step.norm() > most) step *= most / step.norm();
    e_ += step;
    if (e_.norm() > planner::kMaxScanCorrection) e_ *= planner::kMaxScanCorrection / e_.norm();
  }
  if (phase == ScanPhase::Follow) {
    lost_s_ = contact ? 0 : lost_s_ + dt;
    if (lost_s_ > kLostContactBase + 2 * lead) {
      why = FailReason::ScanLostContact;
      return false;
    }
    take_point(*seg, here, delta, contact, now);
  }
  // The correction on the setpoint, within the travel once referenced.
  const AxisVec shift = loop_.config.layout.machine(e_);
  const AxisVec rate = loop_.config.layout.machine((e_ - before) / std::max(dt, 1e-6));
  for (int a = 0; a < loop_.n; ++a) {
    double p = sp.position[a] + shift[a];
    if (loop_.referenced) p = std::clamp(p, loop_.config.axes[a].travel_min, loop_.config.axes[a].travel_max);
    sp.position[a] = p;
    sp.velocity[a] += rate[a];
  }
  return true;
}

}  // namespace imess::core
