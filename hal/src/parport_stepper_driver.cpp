// ParportStepperDriver: servo-rate planning in floating point, base-rate pulse making and
// input capture in integers; the two sides meet only in atomics.
#include "imess/hal/parport_stepper_driver.hpp"

#include "imess/hal/axis_status.hpp"

#include <cmath>
#include <stdexcept>

namespace imess::hal {

namespace {
constexpr unsigned kAllAxes = (1u << kParportAxes) - 1;
std::uint32_t ticks(double ns, double base_ns) { return static_cast<std::uint32_t>(std::ceil(ns / base_ns - 1e-9)); }
}  // namespace

ParportStepperDriver::ParportStepperDriver(PortIo& port, const Clock& clock, ParportStepperConfig config)
    : port_(port), clock_(clock), config_(std::move(config)) {
  validate_pin_map(config_.pins);
  pins_ = compile_pins(config_.pins);
  const double base = config_.base_period_ns;
  if (!(base >= 1000 && base <= 1'000'000)) throw std::invalid_argument("base_period_ns must be from 1000 to 1000000");
  if (!(config_.servo_period_ns >= base)) throw std::invalid_argument("the servo period must be longer than the base period");
  StepTiming t;
  t.step_len = std::max(1u, ticks(config_.step_len_ns, base));
  t.step_space = std::max(1u, ticks(config_.step_space_ns, base));
  t.dir_setup = std::max(1u, ticks(config_.dir_setup_ns, base));
  t.dir_hold = std::max(1u, ticks(config_.dir_hold_ns, base));
  gen_.configure(pins_, t);
  ticks_per_servo_ = static_cast<std::uint64_t>(std::llround(config_.servo_period_ns / base));
  for (int a = 0; a < kParportAxes; ++a) {
    const auto& ax = config_.axes[a];
    if (!(ax.steps_per_mm > 0) || !(ax.max_speed > 0) || !(ax.max_accel > 0))
      throw std::invalid_argument(std::string("axis ") + kAxisLetters[a] + ": steps_per_mm, max_speed and max_accel must be positive");
    vmax_[a] = ax.max_speed * ax.steps_per_mm;
    amax_[a] = ax.max_accel * ax.steps_per_mm;
    if (vmax_[a] > max_step_rate() * (1 + 1e-9))
      throw std::invalid_argument(std::string("axis ") + kAxisLetters[a] + ": max_speed " + std::to_string(ax.max_speed) +
                                  " mm/s needs " + std::to_string(static_cast<long>(vmax_[a])) +
                                  " steps/s, but step length + step space of " +
                                  std::to_string(t.step_len + t.step_space) + " base periods of " +
                                  std::to_string(static_cast<long>(base)) + " ns allow " +
                                  std::to_string(static_cast<long>(max_step_rate())) + " steps/s");
    index_pitch_[a] = ax.index_pitch_mm > 0 ? std::llround(ax.index_pitch_mm * ax.steps_per_mm) : 0;
    index_width_[a] = std::max<std::int64_t>(1, std::llround(ax.index_width_mm * ax.steps_per_mm));
    // The machine stands at initial_position at power-on, where the step count is 0.
    zero_[a] = -std::llround(config_.initial_position[a] * ax.steps_per_mm);
    profile_[a].reset(0);
  }
}

double ParportStepperDriver::max_step_rate() const noexcept {
  const auto& t = gen_.timing();
  return 1e9 / (config_.base_period_ns * (t.step_len + t.step_space));
}

std::int64_t ParportStepperDriver::steps_for(int axis, double mm) const noexcept {
  return std::llround(mm * config_.axes[axis].steps_per_mm) + zero_[axis];
}

void ParportStepperDriver::initialise(bool) {
  // Set-up, before the base routine runs: from then on it alone writes both registers.
  last_data_ = static_cast<std::uint8_t>(gen_.idle_data() ^ output_data_.load(std::memory_order_relaxed));
  port_.out8(data_port(), last_data_);
  last_control_ = control_value(output_control_.load(std::memory_order_relaxed));
  port_.out8(control_port(), last_control_);
  std::uint8_t st = port_.in8(status_port());
  status_.store(st, std::memory_order_relaxed);
  if (port_.errors() != 0)
    throw std::runtime_error("parallel port at " + std::to_string(config_.base) + ": the registers did not answer (" +
                             port_.describe() + ")");
  for (int a = 0; a < kParportAxes; ++a) gen_.command(a, gen_.count(a), 0);
  loops_closed_ = false;
}

std::string ParportStepperDriver::describe() const {
  return "stepper machine on the parallel port (pins '" + config_.pins.name + "', " + port_.describe() + "), up to " +
         std::to_string(static_cast<long>(max_step_rate())) + " steps/s per axis";
}

// ------------------------------------------------------------------ base rate

void ParportStepperDriver::base_tick() noexcept {
  std::uint8_t st = port_.in8(status_port());
  if (active(st, pins_.stop)) halted_.store(true, std::memory_order_relaxed);
  bool halted = halted_.load(std::memory_order_relaxed);
  // Probe: latch every axis at the step count of the contact edge (the first edge is held).
  bool raw = active(st, pins_.probe);
  bool contact = config_.tip_reversed ? !raw : raw;
  if (!base_started_) last_contact_ = contact;
  if (contact && !last_contact_ && !latch_valid_.load(std::memory_order_acquire)) {
    for (int a = 0; a < kParportAxes; ++a) latched_[a].store(gen_.count(a), std::memory_order_relaxed);
    latch_valid_.store(true, std::memory_order_release);
  }
  last_contact_ = contact;
  // Home-side switch releases anchor the synthesised index marks.
  for (int a = 0; a < kParportAxes; ++a) {
    bool sw = active(st, static_cast<std::uint8_t>(pins_.endref[a] | pins_.home[a]));
    if (base_started_ && last_switch_[a] && !sw) release_count_[a].store(gen_.count(a), std::memory_order_relaxed);
    last_switch_[a] = sw;
  }
  base_started_ = true;
  status_.store(st, std::memory_order_release);
  // The user outputs' pins are none of the generator's: their bits come out at the inactive
  // level (the inversion) and flip where the output is on.
  const auto data = static_cast<std::uint8_t>(gen_.tick(halted) ^ output_data_.load(std::memory_order_relaxed));
  if (data != last_data_) {
    port_.out8(data_port(), data);
    last_data_ = data;
  }
  const std::uint8_t control = control_value(output_control_.load(std::memory_order_relaxed));
  if (control != last_control_) {
    port_.out8(control_port(), control);
    last_control_ = control;
  }
}

bool ParportStepperDriver::set_output(int number, bool on) noexcept {
  if (number < 1 || number > pins_.output_count) return false;
  const std::uint8_t data = pins_.output_data[number - 1], control = pins_.output_control[number - 1];
  if (on) {
    output_data_.fetch_or(data, std::memory_order_relaxed);
    output_control_.fetch_or(control, std::memory_order_relaxed);
  } else {
    output_data_.fetch_and(static_cast<std::uint8_t>(~data), std::memory_order_relaxed);
    output_control_.fetch_and(static_cast<std::uint8_t>(~control), std::memory_order_relaxed);
  }
  return true;
}

bool ParportStepperDriver::output_on(int number) const noexcept {
  if (number < 1 || number > pins_.output_count) return false;
  return (output_data_.load(std::memory_order_relaxed) & pins_.output_data[number - 1]) != 0 ||
         (output_control_.load(std::memory_order_relaxed) & pins_.output_control[number - 1]) != 0;
}

// ------------------------------------------------------------------ servo rate

bool ParportStepperDriver::read_state(MachineState& out) noexcept {
  const double dt = servo_interval_.next(clock_.now());

  const std::uint8_t st = status_.load(std::memory_order_acquire);
  const bool halted = halted_.load(std::memory_order_relaxed);
  const bool latch = latch_valid_.load(std::memory_order_acquire);
  const bool raw_probe = active(st, pins_.probe);
  for (int a = 0; a < kParportAxes; ++a) {
    const auto& ax = config_.axes[a];
    const std::int64_t count = gen_.count(a);
    // Inputs in the card's layout; an end/ref switch is the home switch and the limit on its side.
    bool endref = active(st, pins_.endref[a]);
    bool lim_neg = active(st, pins_.limit_neg[a]) || (endref && ax.home_direction < 0);
    bool lim_pos = active(st, pins_.limit_pos[a]) || (endref && ax.home_direction > 0);
    bool home = endref || active(st, pins_.home[a]);
    out.inputs[a] = input_bits(
        {.limit_neg = lim_neg,
         .limit_pos = lim_pos,
         .tip = raw_probe,
         .home = home,
         .index = in_index_window(count - release_count_[a].load(std::memory_order_relaxed), index_pitch_[a],
                                  index_width_[a])});

    lim_neg_[a] = lim_neg;
    lim_pos_[a] = lim_pos;
    TrapezoidPlanner& p = profile_[a];
    if (halted || !loops_closed_) {
      following_[a] = false;
      p.reset(static_cast<double>(count));
      commanded_[a] = count;
      gen_.command(a, count, 0);
    } else if (following_[a] && follow_fresh_ && !((p.heading() < 0 && lim_neg) || (p.heading() > 0 && lim_pos))) {
      // Following: follow() already commanded this period's target; nothing to step here.
    } else {
      if (following_[a]) {  // no setpoint came (the path was dropped) or a limit closed: brake
        following_[a] = false;
        p.stop(amax_[a]);
      }
      p.brake_into_limits(lim_neg, lim_pos, amax_[a]);  // like the card firmware
      p.step(dt);
      command_period(a, std::llround(p.position()));
    }
    const bool arrived = p.done() && count == commanded_[a];
    out.status[a] = status_word({lim_neg, lim_pos, arrived, loops_closed_ && !halted, arrived, latch},
                                halted ? status::kStopInput : 0);
    out.position[a] = static_cast<double>(count - zero_[a]) / ax.steps_per_mm;
  }
  follow_fresh_ = false;
  out.count = kParportAxes;
  out.tip_touched = config_.tip_reversed ? !raw_probe : raw_probe;
  out.deflection_valid = out.probe_over_range = false;  // a touch-trigger probe only: no deflection
  out.deflection = Vec3::Zero();
  return port_.errors() == 0;
}

void ParportStepperDriver::command_period(int a, std::int64_t target, bool path) noexcept {
  const std::int64_t count = gen_.count(a);
  const std::uint64_t need = static_cast<std::uint64_t>(target > count ? target - count : count - target);
  // Spread the steps over the next servo period; the generator caps at its maximum rate.
  // Following a path the rate is rounded up and the steps centred in their intervals, so
  // the last one is out half an interval before the period ends, never late by rounding.
  std::uint64_t rate = 0;
  if (need >= ticks_per_servo_)
    rate = gen_.max_rate();
  else if (path)
    rate = (need * StepGenerator::kOne + ticks_per_servo_ - 1) / ticks_per_servo_;
  else
    rate = std::max<std::uint64_t>(need * StepGenerator::kOne / ticks_per_servo_, need > 0 ? 1 : 0);
  commanded_[a] = target;
  gen_.command(a, target, rate, path);
}

void ParportStepperDriver::leave_following(int a) noexcept {
  following_[a] = false;
  profile_[a].step(config_.servo_period_ns * 1e-9);
  command_period(a, std::llround(profile_[a].position()));
}

// Servo rate, once per period (not measured in bench/ yet: three llround and three integer
// divisions, the same work as a trapezoid period).
bool ParportStepperDriver::follow(const Setpoint& sp) noexcept {
  for (int a = 0; a < kParportAxes; ++a)
    if (!std::isfinite(sp.position[a]) || !std::isfinite(sp.velocity[a])) return false;
  if (!loops_closed_ || halted_.load(std::memory_order_relaxed)) return true;  // like move(): ignored
  for (int a = 0; a < kParportAxes; ++a) {
    const double spm = config_.axes[a].steps_per_mm;
    // Absolute: round(position × steps/mm), so the rounding never accumulates.
    const std::int64_t target = steps_for(a, sp.position[a]);
    const double velocity = sp.velocity[a] * spm;
    const std::int64_t count = gen_.count(a);
    const int heading = velocity != 0 ? (velocity > 0 ? 1 : -1) : (target != count ? (target > count ? 1 : -1) : 0);
    if ((heading < 0 && lim_neg_[a]) || (heading > 0 && lim_pos_[a])) {
      // Into a closed limit switch: this axis brakes as a move() would.
      if (following_[a]) {
        profile_[a].stop(amax_[a]);
        leave_following(a);
      }
      continue;
    }
    // At rest on the path when the setpoint neither moves nor changes: in position as today.
    const bool at_rest = velocity == 0 && following_[a] && target == commanded_[a];
    profile_[a].track(static_cast<double>(target), velocity, at_rest);
    following_[a] = true;
    command_period(a, target, /*path=*/true);
  }
  follow_fresh_ = true;
  return true;
}

bool ParportStepperDriver::read_latch(AxisVec& latched) noexcept {
  for (int a = 0; a < kParportAxes; ++a)
    latched[a] = static_cast<double>(latched_[a].load(std::memory_order_relaxed) - zero_[a]) / config_.axes[a].steps_per_mm;
  latch_valid_.store(false, std::memory_order_release);
  return true;
}

bool ParportStepperDriver::set_loops(bool closed) noexcept {
  if (closed && halted_.load(std::memory_order_relaxed)) return true;  // like the card: a faulted axis stays open
  loops_closed_ = closed;
  for (int a = 0; a < kParportAxes; ++a) {
    following_[a] = false;
    std::int64_t c = gen_.count(a);
    profile_[a].reset(static_cast<double>(c));
    commanded_[a] = c;
    gen_.command(a, c, 0);  // the motors hold where they are
  }
  return true;
}

bool ParportStepperDriver::move(const AxisArray<AxisMove>& moves, unsigned axis_mask) noexcept {
  for (int a = 0; a < kParportAxes; ++a) {
    if (!(axis_mask & (1u << a))) continue;
    const auto& m = moves[a];
    if (!std::isfinite(m.target) || !(m.velocity > 0) || !(m.accel > 0)) return false;
  }
  if (!loops_closed_) return true;  // like the card: an open axis ignores jogs
  for (int a = 0; a < kParportAxes; ++a) {
    if (!(axis_mask & (1u << a))) {
      if (following_[a]) {  // a path no longer fed: that axis brakes
        profile_[a].stop(amax_[a]);
        leave_following(a);
      }
      continue;
    }
    const auto& m = moves[a];
    const double spm = config_.axes[a].steps_per_mm;
    double target = static_cast<double>(steps_for(a, m.target));
    profile_[a].start(target, std::min(m.velocity * spm, vmax_[a]), std::min(m.accel * spm, amax_[a]));
    if (following_[a]) leave_following(a);
  }
  return true;
}

bool ParportStepperDriver::stop(const AxisVec& decel) noexcept {
  for (int a = 0; a < kParportAxes; ++a)
    if (!(decel[a] > 0)) return false;
  for (int a = 0; a < kParportAxes; ++a) {
    profile_[a].stop(std::min(decel[a] * config_.axes[a].steps_per_mm, amax_[a]));
    if (following_[a]) leave_following(a);  // brakes from the path's velocity, starting now
  }
  return true;
}

bool ParportStepperDriver::set_position(int axis, double value) noexcept {
  if (axis < 0 || axis >= kParportAxes || !std::isfinite(value)) return false;
  zero_[axis] = gen_.count(axis) - std::llround(value * config_.axes[axis].steps_per_mm);
  return true;
}

bool ParportStepperDriver::reset_faults() noexcept {
  // STOP is a level: while it is still pressed the next base tick latches it again.
  if (!active(status_.load(std::memory_order_acquire), pins_.stop)) halted_.store(false, std::memory_order_relaxed);
  loops_closed_ = false;
  for (int a = 0; a < kParportAxes; ++a) {
    following_[a] = false;
    std::int64_t c = gen_.count(a);
    profile_[a].reset(static_cast<double>(c));
    commanded_[a] = c;
    gen_.command(a, c, 0);
  }
  return true;
}

}  // namespace imess::hal
