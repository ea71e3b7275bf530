// StraightMoves: jog and GoTo along straight lines, and the motion waiting for rest.
#include "imess/core/straight_moves.hpp"

#include <cmath>

namespace imess::core {

namespace in = hal::input;
namespace st = hal::status;

namespace {
constexpr double kFar = 1e5;  // mm: a jog target beyond any travel when no soft limits are known
}  // namespace

bool StraightMoves::away_from_touch(const AxisVec& u) const noexcept {
  constexpr double kCosAway = 0.5;  // within 60 degrees of straight back along the approach
  return !loop_.approach_dir.isZero() && u.dot(loop_.approach_dir) <= -kCosAway;
}

Refusal StraightMoves::jog(const AxisVec& percent, Nanos now) noexcept {
  const Mode mode = loop_.mode;
  const auto& ms = loop_.ms;
  if (mode == Mode::Fault) return Refusal::Faulted;
  if (mode == Mode::Home || mode == Mode::Path) return Refusal::Busy;  // a queue runs: StopMv first
  const auto& p = loop_.config.params;
  // Every axis at its percentage of MaxSpeed: mm/s on a linear axis, deg/s on a rotary one.
  AxisVec v = percent / 100.0 * p.max_speed * p.speed_level;
  if (percent.isZero()) {  // all speeds zero: the machine stands
    stand_still(now);
    return Refusal::None;
  }
  for (int a = 0; a < loop_.n; ++a)
    if (std::abs(v[a]) < kMinSpeed) v[a] = 0;  // a negligible share does not move the axis
  if (v.isZero()) return Refusal::TooSlow;
  if (mode == Mode::Retract || mode == Mode::Stopping) {  // starts once at rest (and the tip free)
    pending_ = Pending::Jog;
    pending_v_ = percent;
    return Refusal::None;
  }
  if (ms.tip_touched && !away_from_touch(v.normalized())) return Refusal::TipTouched;
  drop_axes_into_limits(v);
  if (v.isZero()) return Refusal::IntoLimit;
  if (mode == Mode::Jog || mode == Mode::Move) {
    if (!ms.motion_done() || loop_.state_stale) {
      loop_.stop_motion();
      pending_ = Pending::Jog;
      pending_v_ = percent;
      loop_.state_stale = true;
      return Refusal::None;
    }
  }
  pending_ = Pending::None;
  const double speed = v.norm();
  AxisVec u = v.normalized();
  return start(jog_target(u), u, speed, Mode::Jog, now);
}

// A jog or move along the line u toward target at path speed speed: notes which limit
// switches it started in, closes the loops, starts every axis.
Refusal StraightMoves::start(const AxisVec& target, const AxisVec& u, double speed, Mode mode, Nanos now) noexcept {
  for (int a = 0; a < loop_.n; ++a) loop_.started_in_limit[a] = loop_.ms.limit_side(a);
  if (!loop_.ms.loops_closed() && !loop_.hw.set_loops(true)) return Refusal::Hardware;
  if (!loop_.hw.move(loop_.straight_moves(target, u, speed), loop_.moving_axes(u))) return Refusal::Hardware;
  loop_.motion_dir = u;
  loop_.enter(mode, now);
  return Refusal::None;
}

// A jog of all-zero speeds: nothing waits, a running jog or move brakes.
void StraightMoves::stand_still(Nanos now) noexcept {
  pending_ = Pending::None;
  if (loop_.mode == Mode::Jog || loop_.mode == Mode::Move) loop_.brake_to_rest(loop_.mode, now);
}

// An axis only moves away from a closed limit switch or, once referenced, a soft limit.
void StraightMoves::drop_axes_into_limits(AxisVec& v) const noexcept {
  const auto& ms = loop_.ms;
  for (int a = 0; a < loop_.n; ++a) {
    int s = sign(v[a]);
    if (s == 0) continue;
    bool in_limit = ms.input(a, s < 0 ? in::kLimitNeg : in::kLimitPos);
    bool at_soft = loop_.referenced && (s < 0 ? ms.position[a] <= loop_.config.axes[a].travel_min + 1e-3
                                              : ms.position[a] >= loop_.config.axes[a].travel_max - 1e-3);
    if (in_limit || at_soft) v[a] = 0;
  }
}

// Where a jog in direction u runs: the end of the travel once referenced, else far away.
AxisVec StraightMoves::jog_target(const AxisVec& u) const noexcept {
  AxisVec target = AxisVec::Zero();
  for (int a = 0; a < loop_.n; ++a) {
    if (u[a] == 0)
      target[a] = loop_.ms.position[a];
    else if (loop_.referenced)
      target[a] = u[a] > 0 ? loop_.config.axes[a].travel_max : loop_.config.axes[a].travel_min;
    else
      target[a] = loop_.ms.position[a] + sign(u[a]) * kFar;
  }
  return target;
}

Refusal StraightMoves::go_to(const AxisVec& given_target, unsigned given, double speed, Nanos now) noexcept {
  const Mode mode = loop_.mode;
  const auto& ms = loop_.ms;
  const auto& config = loop_.config;
  if (mode == Mode::Fault) return Refusal::Faulted;
  if (mode == Mode::Home || mode == Mode::Retract || mode == Mode::Path) return Refusal::Busy;
  AxisVec target = given_target;  // the axes not given stay where they are
  for (int a = 0; a < loop_.n; ++a)
    if (!(given & (1u << a))) target[a] = ms.position[a];
  if (loop_.referenced)
    for (int a = 0; a < loop_.n; ++a)
      if (target[a] < config.axes[a].travel_min || target[a] > config.axes[a].travel_max) return Refusal::OutOfTravel;
  const double v = speed > 0 ? speed : config.params.goto_speed * config.params.speed_level;
  if (v < kMinSpeed) return Refusal::TooSlow;
  if (mode == Mode::Stopping) {
    pending_ = Pending::GoTo;
    pending_v_ = given_target;
    pending_axes_ = given;
    pending_speed_ = speed;
    return Refusal::None;
  }
  if ((mode == Mode::Jog || mode == Mode::Move) && (!ms.motion_done() || loop_.state_stale)) {
    loop_.stop_motion();
    pending_ = Pending::GoTo;
    pending_v_ = given_target;
    pending_axes_ = given;
    pending_speed_ = speed;
    loop_.state_stale = true;
    return Refusal::None;
  }
  pending_ = Pending::None;
  AxisVec d = target - ms.position;
  for (int a = 0; a < loop_.n; ++a)
    if (std::abs(d[a]) < kNegligibleTravel) d[a] = 0;  // this axis stays where it is
  if (d.isZero()) return Refusal::None;
  AxisVec u = d.normalized();
  if (ms.tip_touched && !away_from_touch(u)) return Refusal::TipTouched;
  return start(target, u, v, Mode::Move, now);
}

void StraightMoves::launch_pending(Nanos now) noexcept {
  Pending what = pending_;
  pending_ = Pending::None;
  loop_.enter(Mode::Idle, now);  // at rest: the new motion starts from here
  Refusal r = what == Pending::Jog ? jog(pending_v_, now) : go_to(pending_v_, pending_axes_, pending_speed_, now);
  if (r != Refusal::None) loop_.warn(Warning::MoveRefused, loop_.ms.position, now);
}

void StraightMoves::launch_pending_or_idle(Nanos now) noexcept {
  if (pending_ != Pending::None) launch_pending(now);
  else loop_.enter(Mode::Idle, now);
}

void StraightMoves::update(Nanos now) noexcept {
  const auto& ms = loop_.ms;
  switch (loop_.mode) {
    case Mode::Jog:
      if (pending_ != Pending::None && ms.motion_done()) launch_pending(now);
      else if (ms.motion_done()) loop_.enter(Mode::Idle, now);  // every jogging axis reached its travel end
      break;
    case Mode::Move:
      if (pending_ != Pending::None && ms.motion_done()) launch_pending(now);
      else if (ms.motion_done() && ms.all(st::kInPosition)) loop_.enter(Mode::Idle, now);
      break;
    case Mode::Stopping:
      if (ms.motion_done() && ms.all(st::kInPosition)) launch_pending_or_idle(now);  // every axis at rest
      break;
    default: break;
  }
}

}  // namespace imess::core
