// ScanControl: contact control on a scan's segments (planner/scan.hpp). Every cycle of a scan
// it reads the measuring probe's deflection δ (sampled with the positions) and adds a
// correction e to the planned setpoint: e ← e + (|δ| − set-point)·n̂·period/τ along the
// measured normal n̂ = δ/|δ| (the nominal normal while out of contact), at most 10 mm/s and
// kMaxScanCorrection off the plan. τ is three times the backend's setpoint lead (a streamed
// card runs setpoints that much later than they are sent), at least 30 ms, so the loop cannot
// oscillate. On the Approach it only pushes back (the approach itself closes in); on the Leave
// e fades to zero, so the scan ends exactly at its planned end. On the Follow it takes a point
// every `step` mm: the ball centre's rest position plus δ, moved by the tip radius along −n̂
// (EventKind::ScanPt). Stops with a reason: no measuring probe, contact lost (|δ| below
// kContact for longer than 50 ms plus twice the lead), over range. Real-time: fixed state,
// no allocation, noexcept.
#pragma once
#include "imess/core/loop_context.hpp"
#include "imess/planner/segment.hpp"

namespace imess::core {

class ScanControl {
 public:
  explicit ScanControl(LoopContext& loop) noexcept : loop_(loop) {}

  // A path cycle on segment seg (nullptr: none), `fraction` of its time done: corrects sp (a
  // scan segment) and takes points. False: the scan must stop, for why.
  bool apply(const planner::PlannedSegment* seg, double fraction, hal::Setpoint& sp, double dt, Nanos now,
             FailReason& why) noexcept;
  // The path ended or failed: no correction any more.
  void reset() noexcept;
  // A probe edge now belongs to contact on a scan (the measuring probe deflects by design).
  bool in_contact_phase() const noexcept { return contact_phase_; }
  // The last measured outward normal (machine X Y Z), for backing off after over range.
  const Vec3& measured_normal() const noexcept { return n_hat_; }

  // |δ| below this is no contact, mm.
  static constexpr double kContact = 0.02;

 private:
  Vec3 nominal_normal(const planner::ScanSpec& spec, const Vec3& p) const noexcept;

  LoopContext& loop_;
  Vec3 e_ = Vec3::Zero();        // the correction now, Cartesian mm
  Vec3 e_leave_ = Vec3::Zero();  // the correction when the Leave began
  Vec3 n_hat_ = Vec3::UnitZ();
  Vec3 last_point_ = Vec3::Zero();  // where the ball was last cycle of the Follow
  double travelled_ = 0;            // mm along the path since the last point
  bool have_point_ = false;
  bool contact_phase_ = false;
  planner::ScanPhase phase_ = planner::ScanPhase::None;
  double lost_s_ = 0;  // time out of contact on the Follow
};

}  // namespace imess::core
