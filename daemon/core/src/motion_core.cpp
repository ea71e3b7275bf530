// MotionCore: one allocation-free cycle — the state, the stop lane, the commands, each mode
// to its unit, limits, faults, the snapshot; the parameter lane.
#include "imess/core/motion_core.hpp"

#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

#include "imess/core/path_machine.hpp"  // resolved_limits

namespace imess::core {

namespace st = hal::status;

namespace {
bool moving_mode(Mode m) {
  return m == Mode::Jog || m == Mode::Move || m == Mode::Retract || m == Mode::Home || m == Mode::Stopping ||
         m == Mode::Path;
}
}  // namespace

MotionCore::MotionCore(hal::MotionBackend& hardware, CoreConfig config, hal::SimHooks* sim)
    : loop_(hardware, resolved_limits(std::move(config)), sim), limits_(loop_.config), params_out_(loop_.config.params) {
  params_in_.back() = params_out_;
  params_in_.publish();
  prefault_ring(commands_);  // resident from the start: no RSS creep, no page fault in the cycle
  prefault_ring(loop_.events);  // (the segment ring: PathFollower's constructor)
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
  auto& ms = loop_.ms;
  if (!loop_.hw.read_state(ms)) throw std::runtime_error("the machine did not report its state after initialisation");
  if (ms.count != loop_.n)
    throw std::runtime_error("the backend drives " + std::to_string(ms.count) + " axes, the configuration names " +
                             std::to_string(loop_.n) + " (" + loop_.config.layout.names() + ")");
  loop_.mode = ms.loops_closed() ? Mode::Idle : Mode::Free;
  loop_.mode_since = now;
  for (int a = 0; a < loop_.n; ++a)
    loop_.started_in_limit[a] = ms.limit_side(a);
  outputs_.start(now);
  publish(now);
}

void MotionCore::cycle(Nanos now) noexcept {
  ++cycles_;
  loop_.since_last_s =
      last_cycle_.count() < 0 ? loop_.config.period_s : std::chrono::duration<double>(now - last_cycle_).count();
  last_cycle_ = now;
  if (loop_.since_last_s >= longest_gap_s_ || now - longest_gap_at_ > std::chrono::seconds(1)) {
    longest_gap_s_ = loop_.since_last_s;
    longest_gap_at_ = now;
  }
  loop_.state_stale = false;
  read_machine(now);
  take_stop(now);
  for (int i = 0; i < kCommandsPerCycle && loop_.hw.ready_for_command(); ++i) {
    Command c;
    if (!commands_.pop(c)) break;
    loop_.config.params = params_in_.read();  // a Set sent before this command applies to it
    handle(c, now);
  }
  loop_.config.params = params_in_.read();
  check_limits(now);
  update_mode(now);
  wake_on_departure();
  publish(now);
  if (loop_.pushed) {  // after publish: the io side sees the snapshot of this cycle too
    loop_.pushed = false;
    signal_->notify();
  }
}

void MotionCore::read_machine(Nanos now) noexcept {
  auto& ms = loop_.ms;
  if (!loop_.hw.read_state(ms)) {
    ++loop_.hardware_errors;
    if (++comm_failures_ >= 3 && loop_.mode != Mode::Fault) fault(FaultKind::CommLost, now);
    return;
  }
  comm_failures_ = 0;
  if (ms.faulted() && loop_.mode != Mode::Fault) {
    FaultKind f = ms.any(st::kStopInput)        ? FaultKind::StopInput
                  : ms.any(st::kSafetyInput1)   ? FaultKind::SafetyInput1
                  : ms.any(st::kSafetyInput2)   ? FaultKind::SafetyInput2
                  : ms.any(st::kSafetyInput3)   ? FaultKind::SafetyInput3
                  : ms.any(st::kSafetyInput4)   ? FaultKind::SafetyInput4
                  : ms.any(st::kEmergency)      ? FaultKind::Emergency
                  : ms.any(st::kFollowingError) ? FaultKind::FollowingError
                  : ms.any(st::kDriveNotReady)  ? FaultKind::DriveNotReady
                  : ms.any(st::kLinkErrors)     ? FaultKind::LinkErrors
                  : ms.any(st::kCommTimeout)    ? FaultKind::CommLost
                                                : FaultKind::ConfigError;
    if (f == FaultKind::StopInput) loop_.homed = loop_.referenced = false;  // the step count is no longer trusted
    fault(f, now);
  }
  const bool starved = ms.any(st::kHostStarved);
  if (starved && !host_starved_ && loop_.mode != Mode::Fault) host_stall(now);
  host_starved_ = starved;
  outputs_.refresh();
  if (ms.latch_valid()) probe_.on_latch(now);
}

// The card ran out of setpoints with the path still moving (the loop stalled longer than
// the lead) and braked on the path to rest: no fault. The path's ids fail (HostStall), the
// machine is braked to rest here too and is usable at once (docs/servo-card-link.md).
void MotionCore::host_stall(Nanos now) noexcept {
  Event e;
  e.kind = EventKind::Warn;
  e.warning = Warning::HostStall;
  e.value = static_cast<std::uint32_t>(std::lround(longest_gap_s_ * 1000));
  e.p = loop_.cartesian(loop_.ms.position);
  e.time = now;
  loop_.emit(e);
  if (loop_.mode == Mode::Path) {
    path_.fail_queue(FailReason::HostStall, now);
    loop_.brake_to_rest(Mode::Path, now);
  }
}

// No event, but the io side shows the first change after rest at once.
void MotionCore::wake_on_departure() noexcept {
  if (rest_watch_.left_rest(loop_.ms.position, loop_.n)) {
    ++rest_departures_;
    departure_wakes_ = RestWatch::kDepartureWakes;
  }
  if (departure_wakes_ > 0) {
    --departure_wakes_;
    loop_.pushed = true;
  }
}

// ---------------------------------------------------------------- commands

void MotionCore::take_stop(Nanos now) noexcept {
  const std::uint64_t t = stop_ticket_.load(std::memory_order_acquire);
  if (t == loop_.stop_taken) return;
  loop_.stop_taken = t;
  moves_.drop_pending();
  path_.fail_queue(FailReason::Stopped, now, false);  // also those in the ring sent before it; the io side knows of its stop
  // The stop drops the queue and with it a feed hold (Pause): left on, it held the next queue
  // or program at its start, at rest and without a word (Run after Ctrl-C, abort in messprog).
  path_.resume();
  const Mode m = loop_.mode;
  if (m == Mode::Jog || m == Mode::Move || m == Mode::Home || m == Mode::Path) loop_.brake_to_rest(m, now);
  // Retract: the short move away from the part finishes, then the tip is free (the one
  // exception to "a stop brakes at once": braking would leave the probe deflected).
}

// A Pause too: the stop lane is read ahead of the commands, so a Pause sent just before a stop
// (messprog's Ctrl-C, then "a") would otherwise come after it and hold the next queue.
bool MotionCore::superseded(const Command& c) const noexcept {
  return c.ticket <= loop_.stop_taken &&
         (c.kind == CommandKind::StartMv || c.kind == CommandKind::JogAx || c.kind == CommandKind::GoTo ||
          c.kind == CommandKind::Home || c.kind == CommandKind::Pause);
}

void MotionCore::handle(const Command& c, Nanos now) noexcept {
  if (superseded(c)) return loop_.reply(c, Refusal::None);  // sent before a stop: the stop wins
  switch (c.kind) {
    case CommandKind::StartMv:
    case CommandKind::JogAx: loop_.reply(c, moves_.jog(c.v, now)); return;
    case CommandKind::ForcePt:
      loop_.measured(loop_.cartesian(loop_.ms.position), Vec3::Zero(), false, now);
      loop_.reply(c, Refusal::None);
      return;
    case CommandKind::GoTo: loop_.reply(c, moves_.go_to(c.v, c.axes, c.speed, now)); return;
    case CommandKind::Home: loop_.reply(c, start_homing(now)); return;
    case CommandKind::Free: loop_.reply(c, free_machine(now)); return;
    case CommandKind::Reset: loop_.reply(c, reset(now)); return;
    case CommandKind::Pause:
      path_.hold();
      return loop_.reply(c, Refusal::None);
    case CommandKind::Resume:
      path_.resume();
      return loop_.reply(c, Refusal::None);
    case CommandKind::HandMv: loop_.reply(c, hand_.push(c)); return;
  }
}

Refusal MotionCore::free_machine(Nanos now) noexcept {
  if (moving_mode(loop_.mode)) return Refusal::Busy;
  if (loop_.mode == Mode::Idle) {
    if (!loop_.hw.set_loops(false)) return Refusal::Hardware;
    loop_.enter(Mode::Free, now);
  }
  return Refusal::None;
}

Refusal MotionCore::reset(Nanos now) noexcept {
  if (loop_.mode == Mode::Fault) {
    if (!loop_.hw.reset_faults()) return Refusal::Hardware;
    comm_failures_ = 0;
    loop_.enter(Mode::Free, now);
  }
  return Refusal::None;
}

// ---------------------------------------------------------------- homing

Refusal MotionCore::start_homing(Nanos now) noexcept {
  const Mode m = loop_.mode;
  if (m == Mode::Fault) return Refusal::Faulted;
  if (m == Mode::Home || m == Mode::Retract || m == Mode::Stopping || m == Mode::Path) return Refusal::Busy;
  if (loop_.ms.tip_touched) return Refusal::TipTouched;
  if (moving_mode(m)) loop_.stop_motion();
  if (!loop_.ms.loops_closed() && !loop_.hw.set_loops(true)) return Refusal::Hardware;
  loop_.homed = false;
  homing_.begin(loop_.config, now);
  loop_.motion_dir = AxisVec::Zero();
  loop_.enter(Mode::Home, now);
  return Refusal::None;
}

// One step of the reference search: referenced and idle when done, braking when it failed.
void MotionCore::update_homing(Nanos now) noexcept {
  switch (homing_.step(loop_.ms, loop_.hw, now)) {
    case Homing::Result::Running: break;
    case Homing::Result::Done: {
      loop_.homed = loop_.referenced = true;
      Event e;
      e.kind = EventKind::Homed;
      e.time = now;
      loop_.emit(e);
      loop_.enter(Mode::Idle, now);
      break;
    }
    case Homing::Result::Failed:
      loop_.warn(Warning::HomingFailed, loop_.ms.position, now, homing_.failure());
      loop_.brake_to_rest(Mode::Home, now);
      break;
  }
}

// ---------------------------------------------------------------- limits, modes, faults

void MotionCore::check_limits(Nanos now) noexcept {
  for (int a = 0; a < loop_.n; ++a) {
    int side = loop_.ms.limit_side(a);
    auto& started_in = loop_.started_in_limit[a];
    if (started_in != 0 && side != started_in) started_in = 0;  // left it
    bool entered = side != 0 && side != started_in;
    if (!entered) continue;
    started_in = static_cast<std::int8_t>(side);  // report once per entry
    Event e;
    e.kind = EventKind::Limit;
    e.axis = static_cast<std::int8_t>(a);
    e.side = static_cast<std::int8_t>(side);
    e.time = now;
    loop_.emit(e);
    const Mode m = loop_.mode;
    const bool into = sign(loop_.motion_dir[a]) == side;  // moving into it
    if ((m == Mode::Jog || m == Mode::Move || m == Mode::Retract || m == Mode::Path) && into) {
      moves_.drop_pending();
      path_.fail_queue(FailReason::IntoLimit, now);
      loop_.brake_to_rest(m, now);
    }
  }
}

void MotionCore::update_mode(Nanos now) noexcept {
  if (loop_.state_stale && loop_.mode != Mode::Home) return;  // judge the new motion on fresh state
  switch (loop_.mode) {
    case Mode::Jog:
    case Mode::Move:
    case Mode::Stopping: moves_.update(now); break;
    case Mode::Retract: probe_.update_retract(now); break;
    case Mode::Path: path_.run(now); break;
    case Mode::Idle: update_idle(now); break;
    case Mode::Home: update_homing(now); break;
    case Mode::Free:
      if (path_.fresh_segments_waiting(now)) {
        path_.start(now);
        break;
      }
      hand_.track();
      break;
    case Mode::Fault: break;
  }
}

void MotionCore::update_idle(Nanos now) noexcept {
  if (path_.fresh_segments_waiting(now)) return path_.start(now);
  if (loop_.seconds_in_mode(now) >= loop_.config.params.idle_open_time) {
    if (!loop_.hw.set_loops(false)) ++loop_.hardware_errors;
    loop_.enter(Mode::Free, now);
  }
}

void MotionCore::fault(FaultKind f, Nanos now) noexcept {
  moves_.drop_pending();
  path_.fail_queue(FailReason::Faulted, now);
  loop_.stop_motion();
  if (!loop_.hw.set_loops(false)) ++loop_.hardware_errors;
  Event e;
  e.kind = EventKind::Fault;
  e.fault = f;
  e.p = loop_.cartesian(loop_.ms.position);
  e.time = now;
  loop_.emit(e);
  loop_.enter(Mode::Fault, now);
}

// ---------------------------------------------------------------- snapshot

void MotionCore::publish(Nanos now) noexcept {
  const auto& ms = loop_.ms;
  Snapshot& s = snapshot_.back();
  s.cycle = cycles_;
  s.time = now;
  s.mode = loop_.mode;
  s.position = ms.position;
  s.loops_closed = ms.loops_closed();
  s.tip_touched = ms.tip_touched;
  s.homed = loop_.homed;
  s.referenced = loop_.referenced;
  for (int a = 0; a < loop_.n; ++a)
    s.limit[a] = ms.limit_side(a);
  s.status = ms.status;
  s.inputs = ms.inputs;
  s.params = loop_.config.params;
  s.simulated = loop_.sim != nullptr;
  s.events_dropped = loop_.events_dropped;
  s.hardware_errors = loop_.hardware_errors;
  s.link_errors = loop_.hw.link_errors();
  s.path_running = path_.running();
  s.path_id = path_.running_id();
  s.path_held = path_.holding();
  s.outputs = outputs_.bits();
  s.probe_armed = outputs_.probe_armed(now);
  s.measuring_probe = loop_.ms.deflection_valid;
  s.rest_departures = rest_departures_;
  snapshot_.publish();
}

}  // namespace imess::core
