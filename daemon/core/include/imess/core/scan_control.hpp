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
//
// An unknown contour (ScanPhase::Contour): the setpoint no longer comes from the planned line.
// The commanded ball centre c advances each cycle by the sampled path speed × dt along the
// surface's tangent in the constraint — in a plane: unit(plane normal × n̂); on a cylinder:
// unit(radial × n̂), the cylinder's tangent orthogonal to n̂ — signed to continue the last
// direction (first: ScanContour::direction), plus the correction along n̂ as above, and is
// put back onto the plane or the cylinder. While the deflection is off its set-point by more
// than half the band the advance slows (to a fifth at the band's edge), its speed changing within
// the segment's path acceleration; out of contact it stops (the correction alone seeks the
// surface). The tangent is taken from the measured normal turned on by its rate of turn over
// the lag (setpoint lead + 10 ms), so an edge is followed at speed. Before the first touch
// the correction seeks the surface along the start normal up to the clearance beyond the
// nominal start (then PartNotFound). Points every `step`; every cycle in contact the
// measured surface point is checked against the stop body; at its count-th meeting the scan
// brakes along the surface (still in contact, no more points), holds until the machine has
// followed, and is finished(): the path follower ends it (back off along end_normal, Done as
// a Probe's). A contour whose planned line runs out first ends the same way just before the
// line's end, ran_out(): Failed PartNotFound, backed off along the measured normal.
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
  // An unknown contour met its stop body (apply returned false): the scan ends Done.
  bool finished() const noexcept { return finished_; }
  // An unknown contour is braking toward its end (it met its stop body, or ran_out()).
  bool ending() const noexcept { return ending_; }
  // Its planned length ran out before the stop body was met: it ends Failed PartNotFound.
  bool ran_out() const noexcept { return ran_out_; }
  // The unknown contour's back-off at its end: direction (unit, machine X Y Z) and distance.
  Vec3 end_normal() const noexcept { return end_normal_; }
  double end_clearance() const noexcept { return end_clearance_; }

  // |δ| below this is no contact, mm.
  static constexpr double kContact = 0.02;
  // The fastest correction, mm/s; out of contact this long (plus twice the lead) is lost, s.
  static constexpr double kMaxCorrectionRate = 10;
  static constexpr double kLostContactBase = 0.05;

 private:
  Vec3 nominal_normal(const planner::ScanSpec& spec, const Vec3& p) const noexcept;
  // The unknown contour (scan_contour.cpp): a cycle on its segment, its first cycle, the
  // setpoint of every cycle, the stop body.
  bool contour_cycle(const planner::PlannedSegment& seg, double fraction, hal::Setpoint& sp, double dt, Nanos now,
                     double lead, double tau, FailReason& why) noexcept;
  void begin_contour(const planner::PlannedSegment& seg) noexcept;
  // Advances toward `target` mm/s within `accel`; returns the speed it advanced at.
  double steer(const planner::ScanSpec& spec, bool contact, double target, double accel, double dt, double tau,
               double lag, double error, hal::Setpoint& sp) noexcept;
  bool stop_body_met(const planner::ScanContour& k, const Vec3& surface) noexcept;
  // Takes a point when the path has gone `step` since the last (the Follow, the Contour).
  void take_point(const planner::PlannedSegment& seg, const Vec3& here, const Vec3& delta, bool contact, Nanos now) noexcept;

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
  // The unknown contour.
  Vec3 c_ = Vec3::Zero();        // the commanded ball centre (X Y Z)
  Vec3 t_ = Vec3::UnitX();       // the last tangent
  Vec3 origin_ = Vec3::Zero();   // the touched start: the constraint's plane or cylinder passes through it
  double radius_ = 0;            // the cylinder's radius through it
  double contour_s_ = 0;         // mm of contour behind
  int meetings_ = 0;             // of the stop body so far
  int side_ = 0;                 // the side of the stop body the surface point was on (0: not yet known)
  bool closing_ = false;         // a sphere entered the count-th time: the end is where it is closest
  double closest_ = 0;
  Vec3 turn_rate_ = Vec3::Zero();  // the measured normal's rate of turn, rad/s (axis × angle)
  Vec3 n_last_ = Vec3::UnitZ();
  bool have_turn_ = false;
  bool ran_out_ = false;          // ... because the planned length ran out
  bool ending_ = false;           // met: braking along the surface, then holding
  double speed_ = 0;              // mm/s along the contour now
  bool touched_ = false;          // the surface was touched since the contour began
  double held_s_ = 0;             // s at rest after braking
  bool finished_ = false;
  Vec3 end_normal_ = Vec3::UnitZ();
  double end_clearance_ = 0;
};

}  // namespace imess::core
