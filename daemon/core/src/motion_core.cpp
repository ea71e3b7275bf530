// MotionCore: the 1996 behaviour (jog, limits, probe hit + retract, hand hits, idle loop
// opening, homing) on top of a MotionBackend, in one allocation-free cycle.
#include "imess/core/motion_core.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace imess::core {

namespace in = hal::input;
namespace st = hal::status;

namespace {
constexpr double kFar = 1e5;  // mm: a jog target beyond any travel when no soft limits are known
constexpr unsigned kAllAxes = (1u << kAxes) - 1;

bool moving_mode(Mode m) { return m == Mode::Jog || m == Mode::Move || m == Mode::Retract || m == Mode::Home; }
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
  }
  return p.tip_radius;
}

double param_value(const CoreParams& p, ParamId id) noexcept { return param_ref(const_cast<CoreParams&>(p), id); }

MotionCore::MotionCore(hal::MotionBackend& hardware, CoreConfig config, hal::SimHooks* sim)
    : hw_(hardware), config_(std::move(config)), sim_(sim), referenced_(config_.referenced_at_start) {}

void MotionCore::start(Nanos now) {
  if (!hw_.read_state(ms_)) throw std::runtime_error("the machine did not report its state after initialisation");
  mode_ = ms_.loops_closed() ? Mode::Idle : Mode::Free;
  mode_since_ = now;
  for (int a = 0; a < kAxes; ++a)
    started_in_limit_[a] = static_cast<std::int8_t>(ms_.input(a, in::kLimitNeg) ? -1 : ms_.input(a, in::kLimitPos) ? 1 : 0);
  publish(now);
}

void MotionCore::cycle(Nanos now) noexcept {
  ++cycles_;
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
    if (ms_.latch_valid()) on_probe_latch(now);
  }
  for (int i = 0; i < kCommandsPerCycle; ++i) {
    Command c;
    if (!commands_.pop(c)) break;
    handle(c, now);
  }
  check_limits(now);
  update_mode(now);
  publish(now);
}

// ---------------------------------------------------------------- commands

void MotionCore::handle(const Command& c, Nanos now) noexcept {
  switch (c.kind) {
    case CommandKind::StartMv: reply(c, start_jog(c.v, now)); return;
    case CommandKind::StopMv:
      pending_ = Pending::None;
      if (moving_mode(mode_)) {
        stop_motion();
        enter(Mode::Idle, now);
      }
      reply(c, Refusal::None);
      return;
    case CommandKind::ForcePt:
      measured(ms_.position, Vec3::Zero(), false, now);
      reply(c, Refusal::None);
      return;
    case CommandKind::GoTo: reply(c, go_to(c.v, c.speed, now)); return;
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
    case CommandKind::HandMv:
      if (!sim_) return reply(c, Refusal::NotSimulated);
      if (ms_.loops_closed()) return reply(c, Refusal::LoopsClosed);
      sim_->push_by_hand(c.v, c.speed > 0 ? c.speed : 10.0);
      return reply(c, Refusal::None);
    case CommandKind::SetParam:
      param_ref(config_.params, c.param) = c.value;
      return reply(c, Refusal::None);
  }
}

double MotionCore::effective_speed(double mm_per_s) const noexcept {
  return std::min(mm_per_s, config_.max_velocity);
}

AxisArray<hal::AxisMove> MotionCore::straight_moves(const Vec3& target, const Vec3& u, double speed) const noexcept {
  // Speeds and accelerations in proportion to the direction keep the path on a straight
  // line through acceleration, cruise and braking.
  double umax = u.cwiseAbs().maxCoeff();
  double accel = config_.params.max_accel / (umax > 0 ? umax : 1.0);
  AxisArray<hal::AxisMove> m{};
  for (int a = 0; a < kAxes; ++a) {
    double ua = std::abs(u[a]);
    if (ua < 1e-9)
      m[a] = {target[a], speed, config_.params.max_accel};
    else
      m[a] = {target[a], speed * ua, accel * ua};
  }
  return m;
}

Refusal MotionCore::start_jog(const Vec3& percent, Nanos now) noexcept {
  if (mode_ == Mode::Fault) return Refusal::Faulted;
  if (mode_ == Mode::Home || mode_ == Mode::Retract) return Refusal::Busy;
  if (ms_.tip_touched) return Refusal::TipTouched;
  const auto& p = config_.params;
  Vec3 v = percent / 100.0 * p.max_speed * p.speed_level;
  if (v.isZero()) {  // all speeds zero: the machine stands
    if (moving_mode(mode_)) {
      stop_motion();
      enter(Mode::Idle, now);
    }
    return Refusal::None;
  }
  for (int a = 0; a < kAxes; ++a) {
    int s = sign(v[a]);
    if (s == 0) continue;
    bool in_limit = ms_.input(a, s < 0 ? in::kLimitNeg : in::kLimitPos);
    bool at_soft = referenced_ && (s < 0 ? ms_.position[a] <= config_.axes[a].travel_min + 1e-3
                                         : ms_.position[a] >= config_.axes[a].travel_max - 1e-3);
    if (in_limit || at_soft) v[a] = 0;  // only moves away from a limit
  }
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
  double speed = effective_speed(v.norm());
  Vec3 u = v.normalized();
  Vec3 target;
  for (int a = 0; a < kAxes; ++a) {
    if (u[a] == 0)
      target[a] = ms_.position[a];
    else if (referenced_)
      target[a] = u[a] > 0 ? config_.axes[a].travel_max : config_.axes[a].travel_min;
    else
      target[a] = ms_.position[a] + sign(u[a]) * kFar;
    started_in_limit_[a] =
        static_cast<std::int8_t>(ms_.input(a, in::kLimitNeg) ? -1 : ms_.input(a, in::kLimitPos) ? 1 : 0);
  }
  if (!ms_.loops_closed() && !hw_.set_loops(true)) return Refusal::Hardware;
  auto moves = straight_moves(target, u, speed);
  unsigned mask = 0;
  for (int a = 0; a < kAxes; ++a)
    if (u[a] != 0) mask |= 1u << a;
  if (!hw_.move(moves, mask)) return Refusal::Hardware;
  motion_dir_ = u;
  enter(Mode::Jog, now);
  return Refusal::None;
}

Refusal MotionCore::go_to(const Vec3& target, double speed, Nanos now) noexcept {
  if (mode_ == Mode::Fault) return Refusal::Faulted;
  if (mode_ == Mode::Home || mode_ == Mode::Retract) return Refusal::Busy;
  if (ms_.tip_touched) return Refusal::TipTouched;
  if (referenced_)
    for (int a = 0; a < kAxes; ++a)
      if (target[a] < config_.axes[a].travel_min || target[a] > config_.axes[a].travel_max) return Refusal::OutOfTravel;
  if ((mode_ == Mode::Jog || mode_ == Mode::Move) && (!ms_.motion_done() || state_stale_)) {
    stop_motion();
    pending_ = Pending::GoTo;
    pending_v_ = target;
    pending_speed_ = speed;
    state_stale_ = true;
    return Refusal::None;
  }
  pending_ = Pending::None;
  Vec3 d = target - ms_.position;
  if (d.norm() < 1e-4) return Refusal::None;
  double v = effective_speed(speed > 0 ? speed : config_.params.goto_speed * config_.params.speed_level);
  Vec3 u = d.normalized();
  for (int a = 0; a < kAxes; ++a)
    started_in_limit_[a] =
        static_cast<std::int8_t>(ms_.input(a, in::kLimitNeg) ? -1 : ms_.input(a, in::kLimitPos) ? 1 : 0);
  if (!ms_.loops_closed() && !hw_.set_loops(true)) return Refusal::Hardware;
  if (!hw_.move(straight_moves(target, u, v), kAllAxes)) return Refusal::Hardware;
  motion_dir_ = u;
  enter(Mode::Move, now);
  return Refusal::None;
}

Refusal MotionCore::start_homing(Nanos now) noexcept {
  if (mode_ == Mode::Fault) return Refusal::Faulted;
  if (mode_ == Mode::Home || mode_ == Mode::Retract) return Refusal::Busy;
  if (ms_.tip_touched) return Refusal::TipTouched;
  if (moving_mode(mode_)) stop_motion();
  if (!ms_.loops_closed() && !hw_.set_loops(true)) return Refusal::Hardware;
  homed_ = false;
  homing_.begin(config_, now);
  motion_dir_ = Vec3::Zero();
  enter(Mode::Home, now);
  return Refusal::None;
}

void MotionCore::launch_pending(Nanos now) noexcept {
  Pending what = pending_;
  pending_ = Pending::None;
  enter(Mode::Idle, now);  // at rest: the new motion starts from here
  Refusal r = what == Pending::Jog ? start_jog(pending_v_, now) : go_to(pending_v_, pending_speed_, now);
  if (r != Refusal::None) warn(Warning::MoveRefused, ms_.position, now);
}

void MotionCore::stop_motion() noexcept {
  double umax = motion_dir_.cwiseAbs().maxCoeff();
  double accel = config_.params.max_accel / (umax > 0 ? umax : 1.0);
  Vec3 decel;
  for (int a = 0; a < kAxes; ++a) {
    double ua = std::abs(motion_dir_[a]);
    decel[a] = ua < 1e-9 ? config_.params.max_accel : accel * ua;
  }
  if (!hw_.stop(decel)) ++hardware_errors_;
}

// ---------------------------------------------------------------- probe

void MotionCore::on_probe_latch(Nanos now) noexcept {
  Vec3 latched;
  if (!hw_.read_latch(latched)) {
    ++hardware_errors_;
    return;
  }
  const double r = config_.params.tip_radius;
  switch (mode_) {
    case Mode::Jog:  // a motor hit: the point lies r beyond the ball centre along the motion
      measured(latched + r * motion_dir_, motion_dir_, true, now);
      retract_from(latched, motion_dir_, now);
      return;
    case Mode::Move:
    case Mode::Home: {
      warn(Warning::UnexpectedHit, latched, now);
      Vec3 dir = motion_dir_;
      if (dir.isZero()) {  // homing moves one axis: the overtravel tells the direction
        Vec3 over = ms_.position - latched;
        dir = over.norm() > 1e-6 ? Vec3(over.normalized()) : Vec3(Vec3::UnitZ());
      }
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
      auto dir = hand_.direction_to(latched, config_.params.hand_min_travel);
      if (!dir) {
        warn(Warning::HandHitNoTravel, latched, now);
        return;
      }
      last_hand_hit_ = now;
      measured(latched + r * *dir, *dir, true, now);
      return;
    }
    case Mode::Idle: warn(Warning::HitIgnored, latched, now); return;
  }
}

void MotionCore::retract_from(const Vec3& latched, const Vec3& dir, Nanos now) noexcept {
  Vec3 target = latched - config_.params.retract_distance * dir;
  motion_dir_ = -dir;
  if (!hw_.move(straight_moves(target, -dir, config_.params.retract_speed), kAllAxes)) ++hardware_errors_;
  enter(Mode::Retract, now);
}

// ---------------------------------------------------------------- limits and modes

bool MotionCore::moving_into_limit(int axis, int side) const noexcept {
  return sign(motion_dir_[axis]) == side;
}

void MotionCore::check_limits(Nanos now) noexcept {
  for (int a = 0; a < kAxes; ++a) {
    int side = ms_.input(a, in::kLimitNeg) ? -1 : ms_.input(a, in::kLimitPos) ? 1 : 0;
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
    if ((mode_ == Mode::Jog || mode_ == Mode::Move || mode_ == Mode::Retract) && moving_into_limit(a, side)) {
      stop_motion();
      enter(Mode::Idle, now);
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
    case Mode::Retract:
      if (ms_.motion_done() && ms_.all(st::kInPosition) && !ms_.tip_touched) {
        enter(Mode::Idle, now);
      } else if (in_mode > p.retract_timeout) {
        warn(Warning::TipNotFree, ms_.position, now);
        stop_motion();
        if (!hw_.set_loops(false)) ++hardware_errors_;
        enter(Mode::Free, now);
      }
      break;
    case Mode::Idle:
      if (in_mode >= p.idle_open_time) {
        if (!hw_.set_loops(false)) ++hardware_errors_;
        enter(Mode::Free, now);
      }
      break;
    case Mode::Home:
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
          warn(Warning::HomingFailed, ms_.position, now);
          stop_motion();
          enter(Mode::Idle, now);
          break;
      }
      break;
    case Mode::Free: hand_.update(ms_.position); break;
    case Mode::Fault: break;
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
  stop_motion();
  if (!hw_.set_loops(false)) ++hardware_errors_;
  Event e;
  e.kind = EventKind::Fault;
  e.fault = f;
  e.p = ms_.position;
  e.time = now;
  emit(e);
  enter(Mode::Fault, now);
}

// ---------------------------------------------------------------- output

void MotionCore::emit(const Event& e) noexcept {
  if (!events_.push(e)) ++events_dropped_;
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

void MotionCore::measured(const Vec3& point, const Vec3& dir, bool compensated, Nanos now) noexcept {
  Event e;
  e.kind = EventKind::MeasPt;
  e.p = point;
  e.dir = dir;
  e.compensated = compensated;
  e.radius = compensated ? config_.params.tip_radius : 0.0;
  e.time = now;
  emit(e);
}

void MotionCore::warn(Warning w, const Vec3& where, Nanos now) noexcept {
  Event e;
  e.kind = EventKind::Warn;
  e.warning = w;
  e.p = where;
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
  for (int a = 0; a < kAxes; ++a)
    s.limit[a] = static_cast<std::int8_t>(ms_.input(a, in::kLimitNeg) ? -1 : ms_.input(a, in::kLimitPos) ? 1 : 0);
  s.status = ms_.status;
  s.inputs = ms_.inputs;
  s.params = config_.params;
  s.simulated = sim_ != nullptr;
  s.events_dropped = events_dropped_;
  s.hardware_errors = hardware_errors_;
  snapshot_.publish();
}

}  // namespace imess::core
