// ProbeCycle: probe edges by mode (jog hit, a Probe's hit, unexpected hit, hand hit), retract.
#include "imess/core/probe_cycle.hpp"

#include <algorithm>

#include "imess/core/hand_mode.hpp"
#include "imess/core/outputs.hpp"
#include "imess/core/path_follower.hpp"
#include "imess/core/straight_moves.hpp"

namespace imess::core {

namespace st = hal::status;

void ProbeCycle::on_latch(Nanos now) noexcept {
  AxisVec latched = AxisVec::Zero();
  if (!loop_.hw.read_latch(latched)) {
    ++loop_.hardware_errors;
    return;
  }
  if (!outputs_.probe_armed(now)) {  // the probe's power-on/-off edge, or an unpowered probe: not a hit
    if (outputs_.quiet_edge(now)) return;  // the power-on of start-up: part of set-up, not news
    loop_.warn(Warning::HitIgnored, latched, now,
               outputs_.probe_powered() ? "edge within the probe's arming time; no point taken"
                                        : "probe edge while the probe is switched off; no point taken");
    return;
  }
  const double r = loop_.config.params.tip_radius;
  // Braking after a stop, the hit belongs to the motion that was braking.
  switch (loop_.mode == Mode::Stopping ? loop_.stopped_from : loop_.mode) {
    case Mode::Jog:  // a motor hit: the point lies r beyond the ball centre along the motion
      moves_.drop_pending();
      loop_.approach_dir = loop_.motion_dir;
      if (const Vec3 dir = loop_.cartesian_dir(loop_.motion_dir); !dir.isZero())
        loop_.measured(loop_.cartesian(latched) + r * dir, dir, true, now);
      else  // a jog of axes other than X Y Z only: no approach to compensate along
        loop_.measured(loop_.cartesian(latched), dir, false, now);
      retract_from(latched, loop_.motion_dir, now);
      return;
    case Mode::Path:
      if (path_.in_search()) return probe_hit(latched, now);
      if (path_.in_scan_contact()) return;  // a measuring probe in contact on a scan: no hit
      [[fallthrough]];  // an edge on a move, or on a Probe's fast approach: unexpected
    case Mode::Move:
    case Mode::Home:
    case Mode::Stopping: return unexpected_hit(latched, now);
    case Mode::Retract: return;  // the edge of a bounce while backing off
    case Mode::Free:
    case Mode::Fault: return hand_.hit(latched, now);
    case Mode::Idle: loop_.warn(Warning::HitIgnored, latched, now); return;
  }
}

void ProbeCycle::unexpected_hit(const AxisVec& latched, Nanos now) noexcept {
  moves_.drop_pending();
  path_.fail_queue(FailReason::UnexpectedHit, now);  // a queued segment: Failed id UnexpectedHit
  loop_.warn(Warning::UnexpectedHit, latched, now);
  AxisVec dir = loop_.motion_dir;
  if (dir.isZero()) {  // homing moves one axis: the overtravel tells the direction
    AxisVec over = loop_.ms.position - latched;
    const AxisVec up = loop_.config.layout.machine(Vec3::UnitZ());
    dir = over.norm() > 1e-6 ? AxisVec(over.normalized()) : up.isZero() ? AxisVec(AxisVec::Unit(0)) : up;
  }
  loop_.approach_dir = dir;
  retract_from(latched, dir, now);
}

void ProbeCycle::probe_hit(const AxisVec& latched, Nanos now) noexcept {
  const std::uint32_t id = path_.running_id();
  const AxisVec d = path_.probe_direction();
  const Vec3 cd = loop_.cartesian_dir(d);
  loop_.measured(loop_.cartesian(latched) + loop_.config.params.tip_radius * cd, cd, true, now, id);
  path_.end_search(id, now);
  retracting_ = true;
  scan_end_ = false;
  probe_id_ = id;
  loop_.approach_dir = d;
  retract_from(latched, d, now);
}

void ProbeCycle::close(EventKind k, FailReason why, Nanos now) noexcept {
  if (!retracting_) return;
  retracting_ = false;
  Event e;
  e.kind = k;
  e.id = probe_id_;
  e.fail = why;
  // Done: where the machine stands, the start of what was queued after. A scan's back-off
  // moves only the axes along its end normal: the others stand where the scan left them.
  e.end = scan_end_ ? loop_.ms.position : retract_target_;
  e.p = loop_.cartesian(e.end);
  scan_end_ = false;
  e.probe_end = true;
  e.time = now;
  loop_.emit(e);
}

void ProbeCycle::back_off(const AxisVec& from, const AxisVec& dir, double distance, Nanos now) noexcept {
  loop_.approach_dir = dir;
  retract_by(from, dir, distance, now);
}

void ProbeCycle::finish_scan(std::uint32_t id, const AxisVec& from, const AxisVec& dir, double distance, Nanos now) noexcept {
  retracting_ = true;
  scan_end_ = true;
  probe_id_ = id;
  back_off(from, dir, distance, now);
}

void ProbeCycle::retract_from(const AxisVec& latched, const AxisVec& dir, Nanos now) noexcept {
  retract_by(latched, dir, loop_.config.params.retract_distance, now);
}

void ProbeCycle::retract_by(const AxisVec& latched, const AxisVec& dir, double distance, Nanos now) noexcept {
  // Once referenced, a retract stays within the soft limits too: it is shortened to end
  // at the travel's edge (or does not move) rather than leave it.
  if (loop_.referenced)
    for (int a = 0; a < loop_.n; ++a) {
      const double d = -dir[a];  // the retract's direction
      const auto& ax = loop_.config.axes[a];
      if (d > 0) distance = std::min(distance, std::max(0.0, (ax.travel_max - latched[a]) / d));
      if (d < 0) distance = std::min(distance, std::max(0.0, (latched[a] - ax.travel_min) / -d));
    }
  AxisVec target = latched - distance * dir;
  retract_target_ = target;
  loop_.motion_dir = -dir;
  // The retract first brakes the motion that hit: the configured acceleration, like a stop.
  if (!loop_.hw.move(loop_.straight_moves(target, -dir, loop_.config.params.retract_speed, true), loop_.moving_axes(-dir)))
    ++loop_.hardware_errors;
  loop_.enter(Mode::Retract, now);
}

void ProbeCycle::update_retract(Nanos now) noexcept {
  const auto& ms = loop_.ms;
  if (ms.motion_done() && ms.all(st::kInPosition) && !ms.tip_touched) {
    close(EventKind::Done, FailReason::Stopped, now);
    moves_.launch_pending_or_idle(now);
  } else if (loop_.seconds_in_mode(now) > loop_.config.params.retract_timeout) {
    close(EventKind::Failed, FailReason::TipTouched, now);
    if (moves_.pending()) loop_.warn(Warning::MoveRefused, ms.position, now);
    moves_.drop_pending();
    loop_.warn(Warning::TipNotFree, ms.position, now);
    loop_.stop_motion();
    if (!loop_.hw.set_loops(false)) ++loop_.hardware_errors;
    loop_.enter(Mode::Free, now);
  }
}

}  // namespace imess::core
