// MotionCore: the 1996 behaviour (jog, limits, probe hit + retract, hand hits, idle loop
// opening, homing) on top of a MotionBackend, in one allocation-free cycle.
#include "imess/core/motion_core.hpp"
#include "imess/core/path_machine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace imess::core {

namespace in = hal::input;
namespace st = hal::status;

namespace {
constexpr double kFar = 1e5;  // mm: a jog target beyond any travel when no soft limits are known

bool moving_mode(Mode m) {
  return m == Mode::Jog || m == Mode::Move || m == Mode::Retract || m == Mode::Home || m == Mode::Stopping ||
         m == Mode::Path;
}
// A queued path starts only where the machine stands (mm, per axis).
constexpr double kPathStartTolerance = 0.05;
int sign(double v) { return (v > 0) - (v < 0); }
}  // namespace

double& param_ref(CoreParams& p, ParamId id) noexcept {
  switch (id) {
    case ParamId::TipRadius: return p.tip_radius;
    case ParamId::SpeedLevel: return p.speed_level;
    case ParamId::MaxSpeed: return p.max_speed;
    case ParamId::MaxAccel: return p.max_accel;
    case ParamId::RetractDistance: return p.retract_distance;
    case ParamId::RetractSpeed: return p.retract_speed;
    case ParamId::RetractTimeout: return p.retract_timeout;
    case ParamId::IdleOpenTime: return p.idle_open_time;
    case ParamId::GoToSpeed: return p.goto_speed;
    case ParamId::HandMinTravel: return p.hand_min_travel;
    case ParamId::HandMinInterval: return p.hand_min_interval;
    case ParamId::SearchDistance: return p.search_distance;
    case ParamId::PrehitDistance: return p.prehit_distance;
    case ParamId::ProbeSpeed: return p.probe_speed;
  }
  return p.tip_radius;
}

double param_value(const CoreParams& p, ParamId id) noexcept { return param_ref(const_cast<CoreParams&>(p), id); }

MotionCore::MotionCore(hal::MotionBackend& hardware, CoreConfig config, hal::SimHooks* sim)
    : hw_(hardware),
      config_(resolved_limits(std::move(config))),
      limits_(config_),
      sim_(sim),
      params_out_(config_.params),
      n_(config_.layout.count),
      referenced_(config_.referenced_at_start) {
  params_in_.back() = params_out_;
  params_in_.publish();
  prefault_ring(commands_);  // resident from the start: no RSS creep, no page fault in the cycle
  prefault_ring(events_);
  prefault_ring(segments_);
}

bool MotionCore::submit(Command c) noexcept {
  c.ticket = ++next_ticket_;
  return commands_.push(c);
}

void MotionCore::request_stop() noexcept { stop_ticket_.store(++next_ticket_, std::memory_order_release); }

void MotionCore::set_param(ParamId id, double value) noexcept {
  param_ref(params_out_, id) = value;
  params_in_.back() = params_out_;
  params_in_.publish();
}

void MotionCore::start(Nanos now) {
  if (!hw_.read_state(ms_)) throw std::runtime_error("the machine did not report its state after initialisation");
  if (ms_.count != n_)
    throw std::runtime_error("the backend drives " + std::to_string(ms_.count) + " axes, the configuration names " +
                             std::to_string(n_) + " (" + config_.layout.names() + ")");
  mode_ = ms_.loops_closed() ? Mode::Idle : Mode::Free;
  mode_since_ = now;
  for (int a = 0; a < n_; ++a)
    started_in_limit_[a] = ms_.limit_side(a);
  start_outputs(now);
  publish(now);
}

// Every configured output to its start state; the probe's power-on edge falls in its arming time.
void MotionCore::start_outputs(Nanos now) {
  for (int i = 0; i < config_.output_count; ++i) {
    const OutputSettings& o = config_.outputs[i];
    const std::string name(o.name_view());
    if (o.number < 1 || o.number > hw_.output_count())
      throw std::runtime_error("output '" + name + "' is number " + std::to_string(o.number) + "; the backend has " +
                               (hw_.output_count() ? "outputs 1 to " + std::to_string(hw_.output_count())
                                                   : std::string("no outputs")));
    if (!hw_.set_output(o.number, o.at_start))
      throw std::runtime_error("output '" + name + "' (number " + std::to_string(o.number) + ") could not be switched " +
                               (o.at_start ? "on" : "off") + " at start");
    if (o.probe_power) {
      probe_output_ = i;
      probe_switched(o.at_start, now);
      quiet_arming_ = true;
    }
  }
  refresh_outputs();
}

// The probe's power output switched: edges until its settle time has passed are power edges.
void MotionCore::probe_switched(bool on, Nanos now) noexcept {
  probe_powered_ = on;
  arming_until_ = now + std::chrono::nanoseconds(static_cast<std::int64_t>(config_.outputs[probe_output_].settle_s * 1e9));
}

// The output switches of this sampler tick (SetOutput segments that began, the path at
// rest), in order. The id of the first the backend did not take (nothing after it is
// switched), or nullptr.
const std::uint32_t* MotionCore::switch_outputs(const planner::Sample& smp, Nanos now) noexcept {
  for (int k = 0; k < smp.switch_count; ++k) {
    const auto& sw = smp.switches[k];
    const bool on = sw.value != 0;
    if (!hw_.set_output(sw.output, on)) {
      ++hardware_errors_;
      refresh_outputs();
      return &sw.id;
    }
    if (probe_output_ >= 0 && config_.outputs[probe_output_].number == sw.output) {
      quiet_arming_ = false;
      probe_switched(on, now);
    }
  }
  if (smp.switch_count > 0) refresh_outputs();  // Outputs shows the switch in this cycle's snapshot
  return nullptr;
}

// The outputs as the backend holds them: a trip (a drive kit's safety input) switches them
// off behind the core's back, the probe's power with them.
void MotionCore::refresh_outputs() noexcept {
  for (int i = 0; i < config_.output_count; ++i) {
    const bool on = hw_.output_on(config_.outputs[i].number);
    outputs_on_ = on ? (outputs_on_ | (1u << i)) : (outputs_on_ & ~(1u << i));
    if (i == probe_output_ && !on) probe_powered_ = false;
  }
}

void MotionCore::cycle(Nanos now) noexcept {
  ++cycles_;
  since_last_s_ = last_cycle_.count() < 0 ? config_.period_s : std::chrono::duration<double>(now - last_cycle_).count();
  last_cycle_ = now;
  state_stale_ = false;
  if (!hw_.read_state(ms_)) {
    ++hardware_errors_;
    if (++comm_failures_ >= 3 && mode_ != Mode::Fault) fault(FaultKind::CommLost, now);
  } else {
    comm_failures_ = 0;
    if (ms_.faulted() && mode_ != Mode::Fault) {
      FaultKind f = ms_.any(st::kStopInput)        ? FaultKind::StopInput
                    : ms_.any(st::kSafetyInput1)   ? FaultKind::SafetyInput1
                    : ms_.any(st::kSafetyInput2)   ? FaultKind::SafetyInput2
                    : ms_.any(st::kSafetyInput3)   ? FaultKind::SafetyInput3
                    : ms_.any(st::kSafetyInput4)   ? FaultKind::SafetyInput4
                    : ms_.any(st::kEmergency)      ? FaultKind::Emergency
                    : ms_.any(st::kFollowingError) ? FaultKind::FollowingError
                    : ms_.any(st::kDriveNotReady)  ? FaultKind::DriveNotReady
                    : ms_.any(st::kCommTimeout)    ? FaultKind::CommLost
                                                   : FaultKind::ConfigError;
      if (f == FaultKind::StopInput) homed_ = referenced_ = false;  // the step count is no longer trusted
      fault(f, now);
    }
    refresh_outputs();
    if (ms_.latch_valid()) on_probe_latch(now);
  }
  take_stop(now);
  for (int i = 0; i < kCommandsPerCycle; ++i) {
    Command c;
    if (!commands_.pop(c)) break;
    config_.params = params_in_.read();  // a Set sent before this command applies to it
    handle(c, now);
  }
  config_.params = params_in_.read();
  check_limits(now);
  update_mode(now);
  if (rest_watch_.left_rest(ms_.position, n_)) {
    ++rest_departures_;
    departure_wakes_ = RestWatch::kDepartureWakes;
  }
  if (departure_wakes_ > 0) {  // no event, but the io side shows the first change after rest at once
    --departure_wakes_;
    pushed_ = true;
  }
  publish(now);
  if (pushed_) {  // after publish: the io side sees the snapshot of this cycle too
    pushed_ = false;
    signal_->notify();
  }
}

// ---------------------------------------------------------------- commands

void MotionCore::take_stop(Nanos now) noexcept {
  const std::uint64_t t = stop_ticket_.load(std::memory_order_acquire);
  if (t == stop_taken_) return;
  stop_taken_ = t;
  pending_ = Pending::None;
  fail_queue(FailReason::Stopped, now, false);  // also those in the ring sent before it; the io side knows of its stop
  // The stop drops the queue and with it a feed hold (Pause): left on, it held the next queue
  // or program at its start, at rest and without a word (Run after Ctrl-C, abort in messprog).
  sampler_.resume();
  if (mode_ == Mode::Jog || mode_ == Mode::Move || mode_ == Mode::Home || mode_ == Mode::Path) {
    stop_motion();
    stopped_from_ = mode_;
    enter(Mode::Stopping, now);
  }
  // Retract: the short move away from the part finishes, then the tip is free (the one
  // exception to "a stop brakes at once": braking would leave the probe deflected).
}

// A Pause too: the stop lane is read ahead of the commands, so a Pause sent just before a stop
// (messprog's Ctrl-C, then "a") would otherwise come after it and hold the next queue.
bool MotionCore::superseded(const Command& c) const noexcept {
  return c.ticket <= stop_taken_ &&
         (c.kind == CommandKind::StartMv || c.kind == CommandKind::JogAx || c.kind == CommandKind::GoTo ||
          c.kind == CommandKind::Home || c.kind == CommandKind::Pause);
}

void MotionCore::handle(const Command& c, Nanos now) noexcept {
  if (superseded(c)) return reply(c, Refusal::None);  // sent before a stop: the stop wins
  switch (c.kind) {
    case CommandKind::StartMv:
    case CommandKind::JogAx: reply(c, start_jog(c.v, now)); return;
    case CommandKind::ForcePt:
      measured(cartesian(ms_.position), Vec3::Zero(), false, now);
      reply(c, Refusal::None);
      return;
    case CommandKind::GoTo: reply(c, go_to(c.v, c.axes, c.speed, now)); return;
    case CommandKind::Home: reply(c, start_homing(now)); return;
    case CommandKind::Free:
      if (moving_mode(mode_)) return reply(c, Refusal::Busy);
      if (mode_ == Mode::Idle) {
        if (!hw_.set_loops(false)) return reply(c, Refusal::Hardware);
        enter(Mode::Free, now);
      }
      return reply(c, Refusal::None);
    case CommandKind::Reset:
      if (mode_ == Mode::Fault) {
        if (!hw_.reset_faults()) return reply(c, Refusal::Hardware);
        comm_failures_ = 0;
        enter(Mode::Free, now);
      }
      return reply(c, Refusal::None);
    case CommandKind::Pause:
      sampler_.hold();
      return reply(c, Refusal::None);
    case CommandKind::Resume:
      sampler_.resume();
      return reply(c, Refusal::None);
    case CommandKind::HandMv:
      if (!sim_) return reply(c, Refusal::NotSimulated);
      if (ms_.loops_closed()) return reply(c, Refusal::LoopsClosed);
      sim_->push_by_hand(cartesian(c.v), std::min(c.speed > 0 ? c.speed : 10.0, config_.max_velocity));
      return reply(c, Refusal::None);
  }
}

unsigned MotionCore::moving_axes(const AxisVec& u) const noexcept {
  unsigned mask = 0;
  for (int a = 0; a < n_; ++a)
    if (u[a] != 0) mask |= 1u << a;
  return mask;
}

AxisArray<hal::AxisMove> MotionCore::straight_moves(const AxisVec& target, const AxisVec& u, double speed,
                                                   bool configured_accel) const noexcept {
  // Speeds and accelerations in proportion to the direction keep the path on a straight
  // line through acceleration, cruise and braking; the path values are the largest that
  // keep every moving axis within its own limit.
  double v = std::min(speed, config_.max_velocity), acc = std::numeric_limits<double>::infinity();
  for (int a = 0; a < n_; ++a) {
    const double ua = std::abs(u[a]);
    if (ua == 0) continue;
    const auto& ax = config_.axes[a];
    v = std::min(v, ax.max_velocity / ua);
    acc = std::min(acc, (configured_accel ? ax.max_accel : std::min(config_.params.max_accel, ax.max_accel)) / ua);
  }
  AxisArray<hal::AxisMove> m{};  // the unused axes: 0, never in the mask
  for (int a = 0; a < n_; ++a) {
    const double ua = std::abs(u[a]);
    m[a] = ua == 0 ? hal::AxisMove{ms_.position[a], config_.axes[a].max_velocity, config_.axes[a].max_accel}
                   : hal::AxisMove{target[a], v * ua, acc * ua};
  }
  return m;
}

bool MotionCore::away_from_touch(const AxisVec& u) const noexcept {
  constexpr double kCosAway = 0.5;  // within 60 degrees of straight back along the approach
  return !approach_dir_.isZero() && u.dot(approach_dir_) <= -kCosAway;
}

Refusal MotionCore::start_jog(const AxisVec& percent, Nanos now) noexcept {
  if (mode_ == Mode::Fault) return Refusal::Faulted;
  if (mode_ == Mode::Home || mode_ == Mode::Path) return Refusal::Busy;  // a queue runs: StopMv first
  const auto& p = config_.params;
  // Every axis at its percentage of MaxSpeed: mm/s on a linear axis, deg/s on a rotary one.
  AxisVec v = percent / 100.0 * p.max_speed * p.speed_level;
  if (percent.isZero()) {  // all speeds zero: the machine stands
    stand_still(now);
    return Refusal::None;
  }
  for (int a = 0; a < n_; ++a)
    if (std::abs(v[a]) < kMinSpeed) v[a] = 0;  // a negligible share does not move the axis
  if (v.isZero()) return Refusal::TooSlow;
  if (mode_ == Mode::Retract || mode_ == Mode::Stopping) {  // starts once at rest (and the tip free)
    pending_ = Pending::Jog;
    pending_v_ = percent;
    return Refusal::None;
  }
  if (ms_.tip_touched && !away_from_touch(v.normalized())) return Refusal::TipTouched;
  drop_axes_into_limits(v);
  if (v.isZero()) return Refusal::IntoLimit;
  if (mode_ == Mode::Jog || mode_ == Mode::Move) {
    if (!ms_.motion_done() || state_stale_) {
      stop_motion();
      pending_ = Pending::Jog;
      pending_v_ = percent;
      state_stale_ = true;
      return Refusal::None;
    }
  }
  pending_ = Pending::None;
  const double speed = v.norm();
  AxisVec u = v.normalized();
  return start_straight(jog_target(u), u, speed, Mode::Jog, now);
}

// A jog or move along the line u toward target at path speed speed: notes which limit
// switches it started in, closes the loops, starts every axis.
Refusal MotionCore::start_straight(const AxisVec& target, const AxisVec& u, double speed, Mode mode, Nanos now) noexcept {
  for (int a = 0; a < n_; ++a) started_in_limit_[a] = ms_.limit_side(a);
  if (!ms_.loops_closed() && !hw_.set_loops(true)) return Refusal::Hardware;
  if (!hw_.move(straight_moves(target, u, speed), moving_axes(u))) return Refusal::Hardware;
  motion_dir_ = u;
  enter(mode, now);
  return Refusal::None;
}

// A jog of all-zero speeds: nothing waits, a running jog or move brakes.
void MotionCore::stand_still(Nanos now) noexcept {
  pending_ = Pending::None;
  if (mode_ == Mode::Jog || mode_ == Mode::Move) {
    stop_motion();
    stopped_from_ = mode_;
    enter(Mode::Stopping, now);
  }
}

// An axis only moves away from a closed limit switch or, once referenced, a soft limit.
void MotionCore::drop_axes_into_limits(AxisVec& v) const noexcept {
  for (int a = 0; a < n_; ++a) {
    int s = sign(v[a]);
    if (s == 0) continue;
    bool in_limit = ms_.input(a, s < 0 ? in::kLimitNeg : in::kLimitPos);
    bool at_soft = referenced_ && (s < 0 ? ms_.position[a] <= config_.axes[a].travel_min + 1e-3
                                         : ms_.position[a] >= config_.axes[a].travel_max - 1e-3);
    if (in_limit || at_soft) v[a] = 0;
  }
}

// Where a jog in direction u runs: the end of the travel once referenced, else far away.
AxisVec MotionCore::jog_target(const AxisVec& u) const noexcept {
  AxisVec target = AxisVec::Zero();
  for (int a = 0; a < n_; ++a) {
    if (u[a] == 0)
      target[a] = ms_.position[a];
    else if (referenced_)
      target[a] = u[a] > 0 ? config_.axes[a].travel_max : config_.axes[a].travel_min;
    else
      target[a] = ms_.position[a] + sign(u[a]) * kFar;
  }
  return target;
}

Refusal MotionCore::go_to(const AxisVec& given_target, unsigned given, double speed, Nanos now) noexcept {
  if (mode_ == Mode::Fault) return Refusal::Faulted;
  if (mode_ == Mode::Home || mode_ == Mode::Retract || mode_ == Mode::Path) return Refusal::Busy;
  AxisVec target = given_target;  // the axes not given stay where they are
  for (int a = 0; a < n_; ++a)
    if (!(given & (1u << a))) target[a] = ms_.position[a];
  if (referenced_)
    for (int a = 0; a < n_; ++a)
      if (target[a] < config_.axes[a].travel_min || target[a] > config_.axes[a].travel_max) return Refusal::OutOfTravel;
  const double v = speed > 0 ? speed : config_.params.goto_speed * config_.params.speed_level;
  if (v < kMinSpeed) return Refusal::TooSlow;
  if (mode_ == Mode::Stopping) {
    pending_ = Pending::GoTo;
    pending_v_ = given_target;
    pending_axes_ = given;
    pending_speed_ = speed;
    return Refusal::None;
  }
  if ((mode_ == Mode::Jog || mode_ == Mode::Move) && (!ms_.motion_done() || state_stale_)) {
    stop_motion();
    pending_ = Pending::GoTo;
    pending_v_ = given_target;
    pending_axes_ = given;
    pending_speed_ = speed;
    state_stale_ = true;
    return Refusal::None;
  }
  pending_ = Pending::None;
  AxisVec d = target - ms_.position;
  for (int a = 0; a < n_; ++a)
    if (std::abs(d[a]) < kNegligibleTravel) d[a] = 0;  // this axis stays where it is
  if (d.isZero()) return Refusal::None;
  AxisVec u = d.normalized();
  if (ms_.tip_touched && !away_from_touch(u)) return Refusal::TipTouched;
  return start_straight(target, u, v, Mode::Move, now);
}

Refusal MotionCore::start_homing(Nanos now) noexcept {
  if (mode_ == Mode::Fault) return Refusal::Faulted;
  if (mode_ == Mode::Home || mode_ == Mode::Retract || mode_ == Mode::Stopping || mode_ == Mode::Path)
    return Refusal::Busy;
  if (ms_.tip_touched) return Refusal::TipTouched;
  if (moving_mode(mode_)) stop_motion();
  if (!ms_.loops_closed() && !hw_.set_loops(true)) return Refusal::Hardware;
  homed_ = false;
  homing_.begin(config_, now);
  motion_dir_ = AxisVec::Zero();
  enter(Mode::Home, now);
  return Refusal::None;
}

void MotionCore::launch_pending(Nanos now) noexcept {
  Pending what = pending_;
  pending_ = Pending::None;
  enter(Mode::Idle, now);  // at rest: the new motion starts from here
  Refusal r = what == Pending::Jog ? start_jog(pending_v_, now) : go_to(pending_v_, pending_axes_, pending_speed_, now);
  if (r != Refusal::None) warn(Warning::MoveRefused, ms_.position, now);
}

void MotionCore::stop_motion() noexcept {
  // The configured deceleration of every axis, never the runtime MaxAccel; along a line the
  // path deceleration is the largest every moving axis can give, so the stop stays on it.
  double path = std::numeric_limits<double>::infinity();
  for (int a = 0; a < n_; ++a)
    if (motion_dir_[a] != 0) path = std::min(path, config_.axes[a].max_accel / std::abs(motion_dir_[a]));
  AxisVec decel = AxisVec::Zero();  // the unused axes: 0, never read
  for (int a = 0; a < n_; ++a)
    decel[a] = motion_dir_[a] == 0 ? config_.axes[a].max_accel : path * std::abs(motion_dir_[a]);
  if (!hw_.stop(decel)) ++hardware_errors_;
}

// ---------------------------------------------------------------- probe

void MotionCore::on_probe_latch(Nanos now) noexcept {
  AxisVec latched = AxisVec::Zero();
  if (!hw_.read_latch(latched)) {
    ++hardware_errors_;
    return;
  }
  if (!probe_armed(now)) {  // the probe's power-on/-off edge, or an unpowered probe: not a hit
    if (quiet_arming_ && now < arming_until_) return;  // the power-on of start-up: part of set-up, not news
    warn(Warning::HitIgnored, latched, now, probe_powered_ ? "edge within the probe's arming time; no point taken"
                                                           : "probe edge while the probe is switched off; no point taken");
    return;
  }
  const double r = config_.params.tip_radius;
  // Braking after a stop, the hit belongs to the motion that was braking.
  switch (mode_ == Mode::Stopping ? stopped_from_ : mode_) {
    case Mode::Jog:  // a motor hit: the point lies r beyond the ball centre along the motion
      pending_ = Pending::None;
      approach_dir_ = motion_dir_;
      if (const Vec3 dir = cartesian_dir(motion_dir_); !dir.isZero())
        measured(cartesian(latched) + r * dir, dir, true, now);
      else  // a jog of axes other than X Y Z only: no approach to compensate along
        measured(cartesian(latched), dir, false, now);
      retract_from(latched, motion_dir_, now);
      return;
    case Mode::Path:
      if (held_count_ > 0 && held_probe_[0] == planner::ProbePhase::Search) return probe_hit(latched, now);
      [[fallthrough]];  // an edge on a move, or on a Probe's fast approach: unexpected
    case Mode::Move:
    case Mode::Home:
    case Mode::Stopping: {
      pending_ = Pending::None;
      fail_queue(FailReason::UnexpectedHit, now);  // a queued segment: Failed id UnexpectedHit
      warn(Warning::UnexpectedHit, latched, now);
      AxisVec dir = motion_dir_;
      if (dir.isZero()) {  // homing moves one axis: the overtravel tells the direction
        AxisVec over = ms_.position - latched;
        const AxisVec up = config_.layout.machine(Vec3::UnitZ());
        dir = over.norm() > 1e-6 ? AxisVec(over.normalized()) : up.isZero() ? AxisVec(AxisVec::Unit(0)) : up;
      }
      approach_dir_ = dir;
      retract_from(latched, dir, now);
      return;
    }
    case Mode::Retract: return;  // the edge of a bounce while backing off
    case Mode::Free:
    case Mode::Fault: {  // a hand hit
      if (hal::seconds(now - last_hand_hit_) < config_.params.hand_min_interval) {
        warn(Warning::HandHitTooSoon, latched, now);
        return;
      }
      auto dir = hand_.direction_to(cartesian(latched), config_.params.hand_min_travel);
      if (!dir) {
        warn(Warning::HandHitNoTravel, latched, now);
        return;
      }
      last_hand_hit_ = now;
      approach_dir_ = config_.layout.machine(*dir);
      measured(cartesian(latched) + r * *dir, *dir, true, now);
      return;
    }
    case Mode::Idle: warn(Warning::HitIgnored, latched, now); return;
  }
}

void MotionCore::probe_hit(const AxisVec& latched, Nanos now) noexcept {
  const std::uint32_t id = held_ids_[0];
  const AxisVec d = probe_dir_;
  const Vec3 cd = cartesian_dir(d);
  measured(cartesian(latched) + config_.params.tip_radius * cd, cd, true, now, id);
  held_count_ = 0;  // the search ends here; nothing queued follows it in the ring (the io side holds it)
  QueuedSegment q;
  while (segments_.pop(q))
    if (q.seg.id != id) segment_event(EventKind::Failed, q.seg.id, FailReason::Stopped, now);
  planner::Pose here{};
  for (int a = 0; a < n_; ++a) here[a] = ms_.position[a];
  sampler_.set_position(here);
  probe_retracting_ = true;
  probe_id_ = id;
  approach_dir_ = d;
  retract_from(latched, d, now);
}

void MotionCore::close_probe(EventKind k, FailReason why, Nanos now) noexcept {
  if (!probe_retracting_) return;
  probe_retracting_ = false;
  Event e;
  e.kind = k;
  e.id = probe_id_;
  e.fail = why;
  e.p = cartesian(retract_target_);
  e.end = retract_target_;  // Done: where the machine stands, the start of what was queued after
  e.probe_end = true;
  e.time = now;
  emit(e);
}

void MotionCore::retract_from(const AxisVec& latched, const AxisVec& dir, Nanos now) noexcept {
  // Once referenced, a retract stays within the soft limits too: it is shortened to end
  // at the travel's edge (or does not move) rather than leave it.
  double distance = config_.params.retract_distance;
  if (referenced_)
    for (int a = 0; a < n_; ++a) {
      const double d = -dir[a];  // the retract's direction
      const auto& ax = config_.axes[a];
      if (d > 0) distance = std::min(distance, std::max(0.0, (ax.travel_max - latched[a]) / d));
      if (d < 0) distance = std::min(distance, std::max(0.0, (latched[a] - ax.travel_min) / -d));
    }
  AxisVec target = latched - distance * dir;
  retract_target_ = target;
  motion_dir_ = -dir;
  // The retract first brakes the motion that hit: the configured acceleration, like a stop.
  if (!hw_.move(straight_moves(target, -dir, config_.params.retract_speed, true), moving_axes(-dir))) ++hardware_errors_;
  enter(Mode::Retract, now);
}

// ---------------------------------------------------------------- limits and modes

bool MotionCore::moving_into_limit(int axis, int side) const noexcept {
  return sign(motion_dir_[axis]) == side;
}

void MotionCore::check_limits(Nanos now) noexcept {
  for (int a = 0; a < n_; ++a) {
    int side = ms_.limit_side(a);
    if (started_in_limit_[a] != 0 && side != started_in_limit_[a]) started_in_limit_[a] = 0;  // left it
    bool entered = side != 0 && side != started_in_limit_[a];
    if (!entered) continue;
    started_in_limit_[a] = static_cast<std::int8_t>(side);  // report once per entry
    Event e;
    e.kind = EventKind::Limit;
    e.axis = static_cast<std::int8_t>(a);
    e.side = static_cast<std::int8_t>(side);
    e.time = now;
    emit(e);
    if ((mode_ == Mode::Jog || mode_ == Mode::Move || mode_ == Mode::Retract || mode_ == Mode::Path) &&
        moving_into_limit(a, side)) {
      pending_ = Pending::None;
      fail_queue(FailReason::IntoLimit, now);
      stop_motion();
      stopped_from_ = mode_;
      enter(Mode::Stopping, now);
    }
  }
}

void MotionCore::update_mode(Nanos now) noexcept {
  const auto& p = config_.params;
  double in_mode = hal::seconds(now - mode_since_);
  if (state_stale_ && mode_ != Mode::Home) return;  // judge the new motion on fresh state
  switch (mode_) {
    case Mode::Jog:
      if (pending_ != Pending::None && ms_.motion_done()) launch_pending(now);
      else if (ms_.motion_done()) enter(Mode::Idle, now);  // every jogging axis reached its travel end
      break;
    case Mode::Move:
      if (pending_ != Pending::None && ms_.motion_done()) launch_pending(now);
      else if (ms_.motion_done() && ms_.all(st::kInPosition)) enter(Mode::Idle, now);
      break;
    case Mode::Stopping:
      if (ms_.motion_done() && ms_.all(st::kInPosition)) launch_pending_or_idle(now);  // every axis at rest
      break;
    case Mode::Retract: update_retract(in_mode, now); break;
    case Mode::Path: run_path(now); break;
    case Mode::Idle:
      if (fresh_segments_waiting(now)) {
        start_path(now);
        break;
      }
      if (in_mode >= p.idle_open_time) {
        if (!hw_.set_loops(false)) ++hardware_errors_;
        enter(Mode::Free, now);
      }
      break;
    case Mode::Home: update_homing(now); break;
    case Mode::Free:
      if (fresh_segments_waiting(now)) {
        start_path(now);
        break;
      }
      hand_.update(cartesian(ms_.position));
      break;
    case Mode::Fault: break;
  }
}

// At rest: the motion that waited for it, or idle.
void MotionCore::launch_pending_or_idle(Nanos now) noexcept {
  if (pending_ != Pending::None) launch_pending(now);
  else enter(Mode::Idle, now);
}

// The retract ends in position with the tip free; a tip still touched after retract_timeout
// opens the loops (free), and a motion that waited for the retract is refused.
void MotionCore::update_retract(double in_mode, Nanos now) noexcept {
  if (ms_.motion_done() && ms_.all(st::kInPosition) && !ms_.tip_touched) {
    close_probe(EventKind::Done, FailReason::Stopped, now);
    launch_pending_or_idle(now);
  } else if (in_mode > config_.params.retract_timeout) {
    close_probe(EventKind::Failed, FailReason::TipTouched, now);
    if (pending_ != Pending::None) warn(Warning::MoveRefused, ms_.position, now);
    pending_ = Pending::None;
    warn(Warning::TipNotFree, ms_.position, now);
    stop_motion();
    if (!hw_.set_loops(false)) ++hardware_errors_;
    enter(Mode::Free, now);
  }
}

// One step of the reference search: referenced and idle when done, braking when it failed.
void MotionCore::update_homing(Nanos now) noexcept {
  switch (homing_.step(ms_, hw_, now)) {
    case Homing::Result::Running: break;
    case Homing::Result::Done: {
      homed_ = referenced_ = true;
      Event e;
      e.kind = EventKind::Homed;
      e.time = now;
      emit(e);
      enter(Mode::Idle, now);
      break;
    }
    case Homing::Result::Failed:
      warn(Warning::HomingFailed, ms_.position, now, homing_.failure());
      stop_motion();
      stopped_from_ = Mode::Home;
      enter(Mode::Stopping, now);
      break;
  }
}

void MotionCore::enter(Mode m, Nanos now) noexcept {
  state_stale_ = true;
  if (m == mode_) return;
  mode_ = m;
  mode_since_ = now;
  if (m == Mode::Free) hand_.clear();
  Event e;
  e.kind = EventKind::State;
  e.mode = m;
  e.time = now;
  emit(e);
}

void MotionCore::fault(FaultKind f, Nanos now) noexcept {
  pending_ = Pending::None;
  fail_queue(FailReason::Faulted, now);
  stop_motion();
  if (!hw_.set_loops(false)) ++hardware_errors_;
  Event e;
  e.kind = EventKind::Fault;
  e.fault = f;
  e.p = cartesian(ms_.position);
  e.time = now;
  emit(e);
  enter(Mode::Fault, now);
}

// ---------------------------------------------------------------- path (queued segments)

bool MotionCore::stale(const QueuedSegment& q) const noexcept {
  return q.stop_ticket < stop_taken_ || q.drops != drops_;
}

// Segments sent before a stop or a drop never run: they are failed (Stopped) here, before a
// path starts, so a stale tail does not flicker the state into move and back.
bool MotionCore::fresh_segments_waiting(Nanos now) noexcept {
  while (!segments_.empty() && stale(segments_.front())) {
    QueuedSegment q;
    segments_.pop(q);
    fail_segment(q.seg.id, q.seg.probe, FailReason::Stopped, now);
  }
  return !segments_.empty();
}

// The sampler's source: the ring, minus segments sent before a stop or a drop (each of those
// is Failed Stopped here), and the first segment of a run must start where the machine is.
bool MotionCore::pop_segment(planner::PlannedSegment& out) noexcept {
  QueuedSegment q;
  while (segments_.pop(q)) {
    if (stale(q)) {
      fail_segment(q.seg.id, q.seg.probe, FailReason::Stopped, path_now_);
      continue;
    }
    if (check_start_) {
      check_start_ = false;
      for (int a = 0; a < n_; ++a)
        if (std::abs(q.seg.start[a] - ms_.position[a]) > kPathStartTolerance) {
          fail_segment(q.seg.id, q.seg.probe, FailReason::OffPath, path_now_);
          check_start_ = true;  // the next one must start here too
          break;
        }
      if (check_start_) continue;
    }
    if (held_count_ < static_cast<int>(held_ids_.size())) {
      held_probe_[held_count_] = q.seg.probe;
      held_ids_[held_count_++] = q.seg.id;
    }
    if (q.seg.probe != planner::ProbePhase::None) {
      AxisVec d = AxisVec::Zero();
      for (int a = 0; a < n_; ++a) d[a] = q.seg.end[a] - q.seg.start[a];
      if (d.norm() > 1e-9) probe_dir_ = d / d.norm();
    }
    low_sent_ = false;
    out = q.seg;
    return true;
  }
  return false;
}

// Idle or free with segments waiting: close the loops and follow them from here.
void MotionCore::start_path(Nanos now) noexcept {
  path_now_ = now;
  if (ms_.tip_touched) return fail_queue(FailReason::TipTouched, now);
  planner::Pose here{};
  for (int a = 0; a < n_; ++a) here[a] = ms_.position[a];
  sampler_.set_position(here);
  held_count_ = 0;
  check_start_ = true;
  for (int a = 0; a < n_; ++a) started_in_limit_[a] = ms_.limit_side(a);
  if (!ms_.loops_closed() && !hw_.set_loops(true)) {
    ++hardware_errors_;
    return fail_queue(FailReason::Faulted, now);
  }
  motion_dir_ = AxisVec::Zero();
  enter(Mode::Path, now);
  run_path(now);
}

// One sampler tick: the setpoint to the backend, a Done per completed segment, QueueLow when
// only the running segment is left, idle when the queue ran out at rest.
void MotionCore::run_path(Nanos now) noexcept {
  path_now_ = now;
  // The path's time step: one period, or on a backend that bridges a late setpoint the time
  // that really passed since the last cycle (a stalled host; at most kMaxPathStep, beyond
  // which the card's watchdog has long stopped the machine).
  const double dt = hw_.bridges_late_setpoints() ? std::clamp(since_last_s_, config_.period_s, kMaxPathStep)
                                                 : config_.period_s;
  const planner::Sample& smp = sampler_.advance(dt, [this](planner::PlannedSegment& s) { return pop_segment(s); });
  // The queue ran out at rest: the last Done waits until the machine has arrived (settle).
  const bool resting = sampler_.idle() && !smp.busy;
  if (!resting) release_arrivals(now);  // more came while settling: the machine goes on
  // Outputs switch as their segment begins. One the backend refuses fails from there: the
  // segments completed before it are Done, it and everything after it Failed Faulted.
  const std::uint32_t* refused = switch_outputs(smp, now);
  for (int i = 0; i < smp.done_count; ++i) {
    if (refused && smp.done[i].id == *refused) break;
    // A Probe's approach ends in its search (one id, one Done or Failed); a search that ends
    // without an edge is PartNotFound, the machine at rest at its end.
    const auto phase = smp.done[i].probe;
    if (phase != planner::ProbePhase::Approach) {
      const bool missed = phase == planner::ProbePhase::Search;
      const Arrival end{smp.done[i].id, missed ? EventKind::Failed : EventKind::Done,
                        missed ? FailReason::PartNotFound : FailReason::Stopped};
      if (resting && arrivals_count_ < static_cast<int>(arrivals_.size()))
        arrivals_[arrivals_count_++] = end;
      else
        segment_event(end.kind, end.id, end.why, now);
    }
    if (held_count_ > 0) {
      for (int k = 1; k < held_count_; ++k) {
        held_ids_[k - 1] = held_ids_[k];
        held_probe_[k - 1] = held_probe_[k];
      }
      --held_count_;
    }
  }
  if (refused) {
    fail_queue(FailReason::Faulted, now);
    stop_motion();
    stopped_from_ = Mode::Path;
    enter(Mode::Stopping, now);
    return;
  }
  if (smp.done_count == 0 && resting && held_count_ == 0) {  // nothing came: settle, then idle
    settle(now);
    return;
  }
  // A Probe cycle that begins with the probe switched off fails before it moves on (it could
  // only end in PartNotFound, or in a collision the probe does not see).
  if (held_count_ > 0 && held_probe_[0] != planner::ProbePhase::None && !probe_powered_) {
    fail_queue(FailReason::ProbeOff, now);
    stop_motion();
    stopped_from_ = Mode::Path;
    enter(Mode::Stopping, now);
    return;
  }
  hal::Setpoint sp;
  for (int a = 0; a < n_; ++a) {
    sp.position[a] = smp.pose[a];
    sp.velocity[a] = smp.velocity[a];
  }
  if (sp.velocity.norm() > 1e-9) motion_dir_ = sp.velocity.normalized();  // for a stop's braking line
  if (!hw_.follow(sp)) {  // this backend cannot follow a planned path (or did not answer)
    fail_queue(FailReason::Faulted, now);
    stop_motion();
    stopped_from_ = Mode::Path;
    enter(Mode::Stopping, now);
    return;
  }
  if (resting) {
    settle_since_ = now;  // the last setpoint went out: the machine arrives from here
    return;
  }
  if (held_count_ <= 1 && segments_.empty() && !low_sent_) {
    low_sent_ = true;
    Event e;
    e.kind = EventKind::QueueLow;
    e.time = now;
    emit(e);
  }
}

// The path ended at rest: the machine arrives when every axis reports its profile done and
// in position (the backend's window: 5 µm on the card and the drive kits; steppers at once).
// Then the last Done ids go out and the state is idle, so a client that plans from Done (or
// probes from there) starts where the machine stands, not where it still lags. A backend
// that never reports arrival ends the path after kSettleLimit all the same.
void MotionCore::settle(Nanos now) noexcept {
  const bool arrived = ms_.motion_done() && ms_.all(hal::status::kInPosition);
  if (!arrived && hal::seconds(now - settle_since_) < kSettleLimit) return;
  release_arrivals(now);
  enter(Mode::Idle, now);
}

void MotionCore::release_arrivals(Nanos now) noexcept {
  for (int i = 0; i < arrivals_count_; ++i) segment_event(arrivals_[i].kind, arrivals_[i].id, arrivals_[i].why, now);
  arrivals_count_ = 0;
}

// Fails every queued id (the running one, the buffered one, those in the ring) with why, and
// tells the io side, which fails what it has not sent and plans anew from where the machine
// comes to rest. Segments the io side sends before it hears of this are failed on arrival.
void MotionCore::fail_queue(FailReason why, Nanos now, bool tell) noexcept {
  path_now_ = now;
  release_arrivals(now);  // paths already complete and arriving: Done, not failed
  close_probe(EventKind::Failed, why, now);
  for (int i = 0; i < held_count_; ++i) fail_segment(held_ids_[i], held_probe_[i], why, now);
  held_count_ = 0;
  QueuedSegment q;
  // The stop lane (tell false) fails the segments sent before the stop (stale by their
  // ticket), not those the io side sent after it (a Run or MoveTo in the same write after a
  // StopMv or Abort, or after the controller's disconnect: planned from where the machine
  // stands, since nothing may be planned while it moves); those wait in the ring and start
  // once it stands (start_path checks they start where it is). Failing them too ended such a
  // Run at once, "ProgEnd … failed … Failed Stopped" (tests/golden/test_program_properties.cpp).
  while (!segments_.empty() && (tell || stale(segments_.front()))) {
    segments_.pop(q);
    fail_segment(q.seg.id, q.seg.probe, stale(q) ? FailReason::Stopped : why, now);
  }
  planner::Pose here{};
  for (int a = 0; a < n_; ++a) here[a] = ms_.position[a];
  sampler_.set_position(here);
  if (!tell) return;  // the stop lane: segments sent before it are stale by their ticket
  ++drops_;
  Event e;
  e.kind = EventKind::QueueDropped;
  e.id = drops_;
  e.fail = why;
  e.time = now;
  emit(e);
}

// A Probe's search follows its approach with the same id: one Failed for the two.
void MotionCore::fail_segment(std::uint32_t id, planner::ProbePhase phase, FailReason why, Nanos now) noexcept {
  const bool second_half = phase == planner::ProbePhase::Search && failed_approach_ && failed_id_ == id;
  failed_approach_ = phase == planner::ProbePhase::Approach;
  failed_id_ = id;
  if (!second_half) segment_event(EventKind::Failed, id, why, now);
}

void MotionCore::segment_event(EventKind k, std::uint32_t id, FailReason why, Nanos now) noexcept {
  Event e;
  e.kind = k;
  e.id = id;
  e.fail = why;
  e.time = now;
  emit(e);
}

// ---------------------------------------------------------------- output

void MotionCore::emit(const Event& e) noexcept {
  if (events_.push(e))
    pushed_ = true;
  else
    ++events_dropped_;
}

void MotionCore::reply(const Command& c, Refusal r) noexcept {
  Event e;
  e.kind = EventKind::Reply;
  e.client = c.client;
  e.seq = c.seq;
  e.command = c.kind;
  e.refusal = r;
  emit(e);
}

Vec3 MotionCore::cartesian_dir(const AxisVec& d) const noexcept {
  Vec3 c = cartesian(d);
  const double n = c.norm();
  if (n < 1e-9) return Vec3::Zero();
  return std::abs(n - 1) > 1e-12 ? Vec3(c / n) : c;  // X Y Z alone: already unit, kept to the bit
}

void MotionCore::measured(const Vec3& point, const Vec3& dir, bool compensated, Nanos now, std::uint32_t id) noexcept {
  Event e;
  e.kind = EventKind::MeasPt;
  e.id = id;
  e.p = point;
  e.dir = dir;
  e.compensated = compensated;
  e.radius = compensated ? config_.params.tip_radius : 0.0;
  e.time = now;
  emit(e);
}

void MotionCore::warn(Warning w, const AxisVec& where, Nanos now, const char* reason) noexcept {
  Event e;
  e.kind = EventKind::Warn;
  e.warning = w;
  e.reason = reason;
  e.p = cartesian(where);
  e.time = now;
  emit(e);
}

void MotionCore::publish(Nanos now) noexcept {
  Snapshot& s = snapshot_.back();
  s.cycle = cycles_;
  s.time = now;
  s.mode = mode_;
  s.position = ms_.position;
  s.loops_closed = ms_.loops_closed();
  s.tip_touched = ms_.tip_touched;
  s.homed = homed_;
  s.referenced = referenced_;
  for (int a = 0; a < n_; ++a)
    s.limit[a] = ms_.limit_side(a);
  s.status = ms_.status;
  s.inputs = ms_.inputs;
  s.params = config_.params;
  s.simulated = sim_ != nullptr;
  s.events_dropped = events_dropped_;
  s.hardware_errors = hardware_errors_;
  s.path_running = held_count_ > 0;
  s.path_id = held_count_ > 0 ? held_ids_[0] : 0;
  s.path_held = sampler_.holding();
  s.outputs = outputs_on_;
  s.probe_armed = probe_armed(now);
  s.rest_departures = rest_departures_;
  snapshot_.publish();
}

}  // namespace imess::core
