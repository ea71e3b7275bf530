// PathFollower: queued segments through the Sampler, arrivals, and failing the queue.
#include "imess/core/path_follower.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "imess/core/outputs.hpp"
#include "imess/core/probe_cycle.hpp"

namespace imess::core {

namespace {
// A queued path starts only where the machine stands (mm, per axis).
constexpr double kPathStartTolerance = 0.05;
}  // namespace

PathFollower::PathFollower(LoopContext& loop, Outputs& outputs, ProbeCycle& probe) noexcept
    : loop_(loop), outputs_(outputs), probe_(probe) {
  prefault_ring(segments_);  // resident from the start: no RSS creep, no page fault in the cycle
}

bool PathFollower::stale(const QueuedSegment& q) const noexcept {
  return q.stop_ticket < loop_.stop_taken || q.drops != drops_;
}

void PathFollower::sampler_to_machine() noexcept {
  planner::Pose here{};
  for (int a = 0; a < loop_.n; ++a) here[a] = loop_.ms.position[a];
  sampler_.set_position(here);
}

// Segments sent before a stop or a drop never run: they are failed (Stopped) here, before a
// path starts, so a stale tail does not flicker the state into move and back.
bool PathFollower::fresh_segments_waiting(Nanos now) noexcept {
  while (!segments_.empty() && stale(segments_.front())) {
    QueuedSegment q;
    segments_.pop(q);
    fail_segment(q.seg.id, q.seg.probe, FailReason::Stopped, now, q.seg.scan.phase);
  }
  return !segments_.empty();
}

// The sampler's source: the ring, minus segments sent before a stop or a drop (each of those
// is Failed Stopped here), and the first segment of a run must start where the machine is.
bool PathFollower::pop_segment(planner::PlannedSegment& out) noexcept {
  QueuedSegment q;
  while (segments_.pop(q)) {
    if (stale(q)) {
      fail_segment(q.seg.id, q.seg.probe, FailReason::Stopped, path_now_, q.seg.scan.phase);
      continue;
    }
    if (check_start_) {
      check_start_ = false;
      for (int a = 0; a < loop_.n; ++a)
        if (std::abs(q.seg.start[a] - loop_.ms.position[a]) > kPathStartTolerance) {
          fail_segment(q.seg.id, q.seg.probe, FailReason::OffPath, path_now_, q.seg.scan.phase);
          check_start_ = true;  // the next one must start here too
          break;
        }
      if (check_start_) continue;
    }
    if (held_count_ < static_cast<int>(held_ids_.size())) {
      held_probe_[held_count_] = q.seg.probe;
      held_scan_[held_count_] = q.seg.scan.phase;
      held_ids_[held_count_++] = q.seg.id;
    }
    if (q.seg.probe != planner::ProbePhase::None) {
      AxisVec d = AxisVec::Zero();
      for (int a = 0; a < loop_.n; ++a) d[a] = q.seg.end[a] - q.seg.start[a];
      if (d.norm() > 1e-9) probe_dir_ = d / d.norm();
    }
    low_sent_ = false;
    out = q.seg;
    return true;
  }
  return false;
}

void PathFollower::start(Nanos now) noexcept {
  path_now_ = now;
  if (loop_.ms.tip_touched) return fail_queue(FailReason::TipTouched, now);
  sampler_to_machine();
  held_count_ = 0;
  check_start_ = true;
  for (int a = 0; a < loop_.n; ++a) loop_.started_in_limit[a] = loop_.ms.limit_side(a);
  if (!loop_.ms.loops_closed() && !loop_.hw.set_loops(true)) {
    ++loop_.hardware_errors;
    return fail_queue(FailReason::Faulted, now);
  }
  loop_.motion_dir = AxisVec::Zero();
  loop_.enter(Mode::Path, now);
  run(now);
}

void PathFollower::fail_and_brake(FailReason why, Nanos now) noexcept {
  fail_queue(why, now);
  loop_.brake_to_rest(Mode::Path, now);
}

void PathFollower::run(Nanos now) noexcept {
  path_now_ = now;
  const double period = loop_.config.period_s;
  // The path's time step (hal::MotionBackend::PathTime): one period, or the time that really
  // passed since the last cycle (a stalled host; at most kMaxPathStep, beyond which the card
  // has long stopped the machine).
  double dt = period;
  switch (loop_.hw.path_time()) {
    case hal::MotionBackend::PathTime::PerCycle: break;
    case hal::MotionBackend::PathTime::Bridged: dt = std::clamp(loop_.since_last_s, period, kMaxPathStep); break;
    case hal::MotionBackend::PathTime::OwnClock: dt = std::clamp(loop_.since_last_s, 0.0, kMaxPathStep); break;
  }
  path_time_ += dt;
  const planner::Sample& smp = sampler_.advance(dt, [this](planner::PlannedSegment& s) { return pop_segment(s); });
  // The queue ran out at rest: the last Done waits until the machine has arrived (settle).
  const bool resting = sampler_.idle() && !smp.busy;
  if (!resting) release_arrivals(now);  // more came while settling: the machine goes on
  // Outputs switch as their segment begins. One the backend refuses fails from there: the
  // segments completed before it are Done, it and everything after it Failed Faulted.
  const std::uint32_t* refused = outputs_.switch_for(smp, now);
  // An unknown contour whose planned length ran out before its stop body was met.
  std::optional<std::uint32_t> contour_ran_out;
  for (int i = 0; i < smp.done_count; ++i) {
    if (refused && smp.done[i].id == *refused) break;
    // A Probe's approach ends in its search (one id, one Done or Failed); a search that ends
    // without an edge is PartNotFound, the machine at rest at its end. A scan is done when
    // its Leave is.
    const auto phase = smp.done[i].probe;
    const auto scan = smp.done[i].scan;
    if (scan == planner::ScanPhase::Contour) contour_ran_out = smp.done[i].id;
    if (phase != planner::ProbePhase::Approach && (scan == planner::ScanPhase::None || scan == planner::ScanPhase::Leave)) {
      const bool missed = phase == planner::ProbePhase::Search;
      const Arrival end{smp.done[i].id, missed ? EventKind::Failed : EventKind::Done,
                        missed ? FailReason::PartNotFound : FailReason::Stopped};
      if (resting && arrivals_count_ < static_cast<int>(arrivals_.size()))
        arrivals_[arrivals_count_++] = end;
      else
        loop_.segment_event(end.kind, end.id, end.why, now);
    }
    if (held_count_ > 0) {
      for (int k = 1; k < held_count_; ++k) {
        held_ids_[k - 1] = held_ids_[k];
        held_probe_[k - 1] = held_probe_[k];
        held_scan_[k - 1] = held_scan_[k];
      }
      --held_count_;
    }
  }
  if (refused) return fail_and_brake(FailReason::Faulted, now);
  if (contour_ran_out) {  // its segment is no longer held: failed here, the rest with it
    if (scan_.ending() && !scan_.ran_out()) return contour_end(*contour_ran_out, now);  // it met its stop body just before
    loop_.segment_event(EventKind::Failed, *contour_ran_out, FailReason::PartNotFound, now);
    return scan_stop(FailReason::PartNotFound, now);
  }
  if (smp.done_count == 0 && resting && held_count_ == 0) {  // nothing came: settle, then idle
    settle(now);
    return;
  }
  // A Probe cycle that begins with the probe switched off fails before it moves on (it could
  // only end in PartNotFound, or in a collision the probe does not see).
  const bool probing = held_count_ > 0 && (held_probe_[0] != planner::ProbePhase::None ||
                                           (held_scan_[0] != planner::ScanPhase::None && held_scan_[0] != planner::ScanPhase::Position));
  if (probing && !outputs_.probe_powered()) return fail_and_brake(FailReason::ProbeOff, now);
  hal::Setpoint sp;
  sp.time = path_time_;
  for (int a = 0; a < loop_.n; ++a) {
    sp.position[a] = smp.pose[a];
    sp.velocity[a] = smp.velocity[a];
  }
  // A scan's segment: the contact correction on the setpoint, and its points.
  if (FailReason why{}; !scan_.apply(sampler_.current(), sampler_.current_fraction(), sp, dt, now, why))
    return scan_.finished() && !scan_.ran_out() ? contour_end(sampler_.current()->id, now) : scan_stop(why, now);
  if (sp.velocity.norm() > 1e-9) loop_.motion_dir = sp.velocity.normalized();  // for a stop's braking line
  if (!loop_.hw.follow(sp))  // this backend cannot follow a planned path (or did not answer)
    return fail_and_brake(FailReason::Faulted, now);
  if (resting) {
    settle_since_ = now;  // the last setpoint went out: the machine arrives from here
    return;
  }
  if (held_count_ <= 1 && segments_.empty() && !low_sent_) {
    low_sent_ = true;
    Event e;
    e.kind = EventKind::QueueLow;
    e.time = now;
    loop_.emit(e);
  }
}

// The path ended at rest: the machine arrives when every axis reports its profile done and
// in position (the backend's window: 5 µm on the card and the drive kits; steppers at once).
// Then the last Done ids go out and the state is idle, so a client that plans from Done (or
// probes from there) starts where the machine stands, not where it still lags. A backend
// that never reports arrival ends the path after kSettleLimit all the same.
void PathFollower::settle(Nanos now) noexcept {
  const bool arrived = loop_.ms.motion_done() && loop_.ms.all(hal::status::kInPosition);
  if (!arrived && hal::seconds(now - settle_since_) < kSettleLimit) return;
  release_arrivals(now);
  scan_.reset();
  loop_.enter(Mode::Idle, now);
}

void PathFollower::release_arrivals(Nanos now) noexcept {
  for (int i = 0; i < arrivals_count_; ++i)
    loop_.segment_event(arrivals_[i].kind, arrivals_[i].id, arrivals_[i].why, now);
  arrivals_count_ = 0;
}

// Segments the io side sends before it hears of a drop are failed on arrival (stale).
void PathFollower::fail_queue(FailReason why, Nanos now, bool tell) noexcept {
  path_now_ = now;
  release_arrivals(now);  // paths already complete and arriving: Done, not failed
  probe_.close(EventKind::Failed, why, now);
  for (int i = 0; i < held_count_; ++i) fail_segment(held_ids_[i], held_probe_[i], why, now, held_scan_[i]);
  held_count_ = 0;
  scan_.reset();
  QueuedSegment q;
  // The stop lane (tell false) fails the segments sent before the stop (stale by their
  // ticket), not those the io side sent after it (a Run or MoveTo in the same write after a
  // StopMv or Abort, or after the controller's disconnect: planned from where the machine
  // stands, since nothing may be planned while it moves); those wait in the ring and start
  // once it stands (start checks they start where it is). Failing them too ended such a
  // Run at once, "ProgEnd … failed … Failed Stopped" (tests/golden/test_program_properties.cpp).
  while (!segments_.empty() && (tell || stale(segments_.front()))) {
    segments_.pop(q);
    fail_segment(q.seg.id, q.seg.probe, stale(q) ? FailReason::Stopped : why, now, q.seg.scan.phase);
  }
  sampler_to_machine();
  if (!tell) return;  // the stop lane: segments sent before it are stale by their ticket
  ++drops_;
  Event e;
  e.kind = EventKind::QueueDropped;
  e.id = drops_;
  e.fail = why;
  e.time = now;
  loop_.emit(e);
}

// A Probe's search follows its approach with the same id: one Failed for the two; a scan's
// segments all carry the scan's id: one Failed for them all.
void PathFollower::fail_segment(std::uint32_t id, planner::ProbePhase phase, FailReason why, Nanos now,
                                planner::ScanPhase scan) noexcept {
  const bool in_scan = scan != planner::ScanPhase::None;
  const bool second_half = failed_id_ == id && ((phase == planner::ProbePhase::Search && failed_approach_) ||
                                                (in_scan && scan != planner::ScanPhase::Position && failed_scan_));
  failed_approach_ = phase == planner::ProbePhase::Approach;
  failed_scan_ = in_scan;
  failed_id_ = id;
  if (!second_half) loop_.segment_event(EventKind::Failed, id, why, now);
}

void PathFollower::scan_stop(FailReason why, Nanos now) noexcept {
  const Vec3 n = scan_.measured_normal();
  const double pressed = loop_.ms.deflection.norm();
  fail_queue(why, now);
  // Over range, or an unknown contour that ran out of its length in contact: off the surface
  // along its normal (brake, then back off).
  if (why == FailReason::ScanOverRange || why == FailReason::PartNotFound)
    return probe_.back_off(loop_.ms.position, -loop_.config.layout.machine(n), pressed + loop_.config.params.retract_distance, now);
  loop_.brake_to_rest(Mode::Path, now);
}

void PathFollower::contour_end(std::uint32_t id, Nanos now) noexcept {
  const AxisVec out = loop_.config.layout.machine(scan_.end_normal());
  const double distance = loop_.ms.deflection.norm() + scan_.end_clearance();
  end_search(id, now);
  probe_.finish_scan(id, loop_.ms.position, -out, distance, now);
}

void PathFollower::end_search(std::uint32_t id, Nanos now) noexcept {
  held_count_ = 0;  // the search ends here; nothing queued follows it in the ring (the io side holds it)
  scan_.reset();
  QueuedSegment q;
  while (segments_.pop(q))
    if (q.seg.id != id) loop_.segment_event(EventKind::Failed, q.seg.id, FailReason::Stopped, now);
  sampler_to_machine();
}

}  // namespace imess::core
