// DriveKitDriver: one servo period = read counters and inputs, safety first, set points,
// PID + feed-forward with anti-windup, write the DACs (or increments), strobe.
#include "imess/hal/drive_kit_driver.hpp"

#include "imess/hal/axis_status.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace imess::hal {

namespace {
constexpr std::array<std::uint32_t, 4> kSafetyStatus{status::kSafetyInput1, status::kSafetyInput2, status::kSafetyInput3,
                                                     status::kSafetyInput4};

// Counts moved since the last 16-bit read (the signed difference: a counter never moves half
// its range between two reads).
std::int16_t counts_since(std::uint16_t raw, std::uint16_t last_raw) noexcept {
  return static_cast<std::int16_t>(static_cast<std::uint16_t>(raw - last_raw));
}
}  // namespace

std::optional<DriveKitConfig> named_drive_kit_map(std::string_view name, int count) {
  if (count < 1 || count > kMaxAxes) return std::nullopt;
  DriveKitConfig c;
  c.layout.count = count;
  std::uint16_t command, position, latch;
  if (name == "mrm-a") {
    c.sync_port = 0x300;
    command = 0x301;
    position = 0x306;
    c.inputs_port = 0x30B;
    c.outputs_port = 0x30C;
    latch = 0x30D;
  } else if (name == "mrm-b") {
    c.sync_port = 0x300;
    c.outputs_port = 0x303;
    c.inputs_port = 0x304;
    command = 0x306;
    position = 0x30B;
    latch = 0x310;
  } else {
    return std::nullopt;
  }
  c.latch_status_port = static_cast<std::uint16_t>(latch + count);
  if (count > 3) c.inputs2_port = static_cast<std::uint16_t>(c.latch_status_port + 1);
  for (int a = 0; a < count; ++a) {
    auto& ax = c.axes[a];
    auto i = static_cast<std::uint16_t>(a);
    ax.command_port = static_cast<std::uint16_t>(command + i);
    ax.position_port = static_cast<std::uint16_t>(position + i);
    ax.latch_port = static_cast<std::uint16_t>(latch + i);
    ax.inputs_bank = a < 3 ? 0 : 1;
    const int slot = a < 3 ? a : a - 3;  // three bits per axis, five axes per bank at most
    if (slot < 5) {
      ax.limit_neg_bit = static_cast<std::uint16_t>(0x1u << (3 * slot));
      ax.limit_pos_bit = static_cast<std::uint16_t>(0x2u << (3 * slot));
      ax.home_bit = static_cast<std::uint16_t>(0x4u << (3 * slot));
    }
    ax.enable_bit = static_cast<std::uint16_t>(1u << a);
  }
  if (name == "mrm-a") {  // above the enables 1 << axis (bits 0..8)
    c.output_count = 7;
    for (int i = 0; i < c.output_count; ++i) c.outputs[i] = {c.outputs_port, static_cast<std::uint16_t>(1u << (9 + i))};
  } else {  // 0x302: bit 0 the manual's gripper, the rest free
    c.output_count = 8;
    for (int i = 0; i < c.output_count; ++i) c.outputs[i] = {0x302, static_cast<std::uint16_t>(1u << i)};
  }
  return c;
}

namespace {
std::string hex(std::uint16_t v) {
  static const char* digits = "0123456789ABCDEF";
  std::string s = "0x";
  bool any = false;
  for (int shift = 12; shift >= 0; shift -= 4) {
    const int d = (v >> shift) & 0xF;
    if (d || any || shift == 0) s += digits[d];
    any = any || d;
  }
  return s;
}
int bit_of(std::uint16_t mask) {
  for (int b = 0; b < 16; ++b)
    if (mask == (1u << b)) return b;
  return -1;
}
}  // namespace

void validate_drive_kit_outputs(const DriveKitConfig& c) {
  if (c.output_count < 0 || c.output_count > kMaxDriveKitOutputs)
    throw std::invalid_argument("at most " + std::to_string(kMaxDriveKitOutputs) + " user outputs");
  for (int i = 0; i < c.output_count; ++i) {
    const PortBit& o = c.outputs[i];
    const int bit = bit_of(o.mask);
    const std::string name = "output " + std::to_string(i + 1) + " (port " + hex(o.port) +
                             (bit >= 0 ? " bit " + std::to_string(bit) : " mask " + hex(o.mask)) + ")";
    if (o.port == 0 || bit < 0) throw std::invalid_argument(name + ": an output is one bit (0-15) of a port other than 0");
    auto refuse = [&](const std::string& what) {
      throw std::invalid_argument(name + ": " + what + "; give a free output bit");
    };
    if (o.port == c.inputs_port || (c.inputs2_port && o.port == c.inputs2_port)) refuse("that is an inputs port");
    if (c.sync_port && o.port == c.sync_port) refuse("that is the sync port");
    if (c.latch_status_port && o.port == c.latch_status_port) refuse("that is the latch status port");
    for (int a = 0; a < c.layout.count; ++a) {
      const auto& ax = c.axes[a];
      const char letter = c.layout.letters[a];
      const std::string axis = "axis " + (letter ? std::string(1, letter) : std::to_string(a + 1)) + "'s ";
      if (o.port == ax.command_port) refuse("that is " + axis + "command port");
      if (o.port == ax.position_port) refuse("that is " + axis + "position port");
      if (ax.latch_port && o.port == ax.latch_port) refuse("that is " + axis + "counter latch port");
      if (o.port == c.outputs_port && (o.mask & ax.enable_bit)) refuse("that is " + axis + "amplifier enable");
    }
    for (int j = 0; j < i; ++j)
      if (c.outputs[j].port == o.port && c.outputs[j].mask == o.mask) refuse("output " + std::to_string(j + 1) + " is that bit already");
  }
}

DriveKitDriver::DriveKitDriver(PortIo& port, const Clock& clock, DriveKitConfig config)
    : port_(port), clock_(clock), config_(std::move(config)) {
  if (config_.mode != 1 && config_.mode != 2) throw std::invalid_argument("drive kit mode must be 1 (DAC mV) or 2 (increments)");
  for (int a = 0; a < n(); ++a) {
    const auto& ax = config_.axes[a];
    std::string name = std::string("axis ") + config_.layout.letters[a];
    if (!(ax.position_unit_mm > 0) || !(ax.mv_per_mm_s > 0) || !(ax.max_speed > 0) || !(ax.max_accel > 0) ||
        !(ax.max_following_error > 0))
      throw std::invalid_argument(name + ": position_unit_mm, mv_per_mm_s, max_speed, max_accel and max_following_error must be positive");
    if (config_.mode == 1 && ax.max_speed * ax.mv_per_mm_s > config_.dac_limit_mv)
      throw std::invalid_argument(name + ": max_speed needs " + std::to_string(ax.max_speed * ax.mv_per_mm_s) +
                                  " mV, beyond the DAC's " + std::to_string(config_.dac_limit_mv) + " mV");
    // 16 bits of counts must not wrap between two reads.
    if (ax.max_speed * config_.servo_period_ns * 1e-9 / ax.position_unit_mm > 16000)
      throw std::invalid_argument(name + ": max_speed moves more than 16000 counts per servo period; the 16-bit position port would wrap unseen");
  }
  validate_drive_kit_outputs(config_);
  for (int i = 0; i < config_.output_count; ++i) {
    const PortBit& o = config_.outputs[i];
    if (o.port == config_.outputs_port) {
      output_slot_[i] = -1;
      user_bits_on_outputs_port_ |= o.mask;
      continue;
    }
    int slot = 0;
    while (slot < shadow_count_ && shadow_ports_[slot] != o.port) ++slot;
    if (slot == shadow_count_) shadow_ports_[shadow_count_++] = o.port;
    output_slot_[i] = static_cast<std::int8_t>(slot);
  }
}

double DriveKitDriver::position(int a) const noexcept {
  return static_cast<double>(axes_[a].count) * config_.axes[a].position_unit_mm - axes_[a].offset;
}

std::uint16_t DriveKitDriver::enable_bits() const noexcept {
  std::uint16_t b = 0;
  for (int a = 0; a < n(); ++a) b |= config_.axes[a].enable_bit;
  return b;
}

void DriveKitDriver::initialise(bool) {
  for (int a = 0; a < n(); ++a) {
    const auto& ax = config_.axes[a];
    port_.out16(ax.command_port, 0);
    // Place the 16 bits read nearest to where the machine is said to stand.
    std::uint16_t raw = port_.in16(ax.position_port);
    auto near = static_cast<std::int64_t>(std::llround(config_.initial_position[a] / ax.position_unit_mm));
    axes_[a].count = near + counts_since(raw, static_cast<std::uint16_t>(near));
    axes_[a].last_raw = raw;
    axes_[a].profile.reset(position(a));
  }
  outputs_ = static_cast<std::uint16_t>(config_.safe_outputs & ~user_bits_on_outputs_port_);
  port_.out16(config_.outputs_port, outputs_);
  user_outputs_off();
  if (config_.latch_status_port) port_.out16(config_.latch_status_port, 0);
  if (port_.errors() != 0) throw std::runtime_error("drive kit: the ports did not answer (" + port_.describe() + ")");
  loops_closed_ = false;
}

std::string DriveKitDriver::describe() const {
  return std::string("drive kit on port I/O, mode ") + (config_.mode == 1 ? "1 (DAC mV)" : "2 (increments)") + ", " +
         port_.describe();
}

void DriveKitDriver::write_command(int a, double velocity) noexcept {
  const auto& ax = config_.axes[a];
  if (config_.mode == 1) {
    double mv = std::clamp(velocity * ax.mv_per_mm_s, -config_.dac_limit_mv, config_.dac_limit_mv);
    port_.out16(ax.command_port, static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(mv))));
    return;
  }
  // Mode 2: increments for this period; the fraction is carried, never dropped.
  Axis& s = axes_[a];
  double want = velocity * config_.servo_period_ns * 1e-9 / ax.position_unit_mm + s.remainder;
  double n = std::clamp(std::trunc(want), -32767.0, 32767.0);
  if (port_.in16(ax.command_port) != 0) {  // the kit has not taken the last one
    ++handshake_misses_;
    s.remainder = want;
    return;
  }
  s.remainder = want - n;
  port_.out16(ax.command_port, static_cast<std::uint16_t>(static_cast<std::int16_t>(n)));
}

void DriveKitDriver::safe_state(std::uint16_t outputs) noexcept {
  for (int a = 0; a < n(); ++a) {
    port_.out16(config_.axes[a].command_port, 0);
    axes_[a].profile.reset(position(a));
    axes_[a].integral = axes_[a].remainder = 0;
    axes_[a].following = false;
  }
  outputs_ = static_cast<std::uint16_t>(outputs & ~user_bits_on_outputs_port_);
  port_.out16(config_.outputs_port, outputs_);
  user_outputs_off();
  loops_closed_ = false;
}

// The other ports' user outputs off (those on the outputs port go with outputs_).
void DriveKitDriver::user_outputs_off() noexcept {
  for (int s = 0; s < shadow_count_; ++s) {
    for (int i = 0; i < config_.output_count; ++i)
      if (output_slot_[i] == s) shadow_words_[s] = static_cast<std::uint16_t>(shadow_words_[s] & ~config_.outputs[i].mask);
    port_.out16(shadow_ports_[s], shadow_words_[s]);
  }
}

std::uint16_t& DriveKitDriver::shadow(int output) noexcept {
  return output_slot_[output] < 0 ? outputs_ : shadow_words_[output_slot_[output]];
}

bool DriveKitDriver::output_on(int number) const noexcept {
  if (number < 1 || number > config_.output_count) return false;
  const int slot = output_slot_[number - 1];
  return ((slot < 0 ? outputs_ : shadow_words_[slot]) & config_.outputs[number - 1].mask) != 0;
}

bool DriveKitDriver::set_output(int number, bool on) noexcept {
  if (number < 1 || number > config_.output_count) return false;
  if (on && safety_faults_ != 0) return false;  // a safety input holds the outputs off until Reset
  const PortBit& o = config_.outputs[number - 1];
  std::uint16_t& word = shadow(number - 1);
  const auto next = static_cast<std::uint16_t>(on ? (word | o.mask) : (word & ~o.mask));
  const unsigned long errors = port_.errors();
  port_.out16(o.port, next);
  if (port_.errors() != errors) return false;  // not written: the shadow keeps what the port holds
  word = next;
  return true;
}

// ------------------------------------------------------------------ one servo period

bool DriveKitDriver::read_state(MachineState& out) noexcept {
  const double dt = servo_interval_.next(clock_.now());
  const std::uint16_t in = port_.in16(config_.inputs_port);
  const std::array<std::uint16_t, 2> banks{in, config_.inputs2_port ? port_.in16(config_.inputs2_port) : std::uint16_t{0}};
  trip_safety_inputs(in);  // safety first
  widen_counters();
  const bool raw_probe = (in & config_.probe_bit) != 0;
  const bool contact = config_.tip_reversed ? !raw_probe : raw_probe;
  latch_probe(contact);
  bool following_fault = false;
  for (int a = 0; a < n(); ++a) {
    out.inputs[a] = sample_inputs(a, banks, raw_probe);
    following_fault |= servo_axis(a, out.input(a, input::kLimitNeg), out.input(a, input::kLimitPos), dt);
  }
  if (following_fault) safe_state(config_.safe_outputs);
  follow_fresh_ = false;
  out.count = n();
  if (config_.sync_port) port_.out16(config_.sync_port, ++strobe_);
  for (int a = 0; a < n(); ++a) {
    out.status[a] = axis_status(a, out);
    out.position[a] = position(a);
  }
  out.tip_touched = contact;
  out.deflection_valid = out.probe_over_range = false;  // a touch-trigger probe only: no deflection
  out.deflection = Vec3::Zero();
  return port_.errors() == 0;
}

std::uint32_t DriveKitDriver::open_safety_inputs(std::uint16_t in) const noexcept {
  std::uint32_t open = 0;
  for (int i = 0; i < 4; ++i)
    if (config_.safety_bits[i] && !(in & config_.safety_bits[i])) open |= kSafetyStatus[i];
  return open;
}

// A normally-closed input reading open stops everything this period.
void DriveKitDriver::trip_safety_inputs(std::uint16_t in) noexcept {
  const std::uint32_t tripped = open_safety_inputs(in);
  if (tripped & ~safety_faults_) safe_state(config_.safe_outputs);
  safety_faults_ |= tripped;
}

// Counters: 16 bits widened by the signed difference since the last read.
void DriveKitDriver::widen_counters() noexcept {
  for (int a = 0; a < n(); ++a) {
    std::uint16_t raw = port_.in16(config_.axes[a].position_port);
    axes_[a].count += counts_since(raw, axes_[a].last_raw);
    axes_[a].last_raw = raw;
  }
}

// Probe: the counters' latch, or the input sampled now.
void DriveKitDriver::latch_probe(bool contact) noexcept {
  if (config_.latch_status_port) {
    if (!latch_valid_ && (port_.in16(config_.latch_status_port) & 1)) {
      for (int a = 0; a < n(); ++a) {
        const auto& ax = config_.axes[a];
        std::int64_t c = axes_[a].count + counts_since(port_.in16(ax.latch_port), axes_[a].last_raw);
        latched_[a] = static_cast<double>(c) * ax.position_unit_mm - axes_[a].offset;
      }
      latch_valid_ = true;
    }
  } else if (contact && !last_contact_ && !latch_valid_) {
    for (int a = 0; a < n(); ++a) latched_[a] = position(a);
    latch_valid_ = true;
  }
  last_contact_ = contact;
}

// The axis' input bits in the card's layout; notes where the home switch released (the
// synthesised index counts from there).
std::uint8_t DriveKitDriver::sample_inputs(int a, const std::array<std::uint16_t, 2>& banks, bool raw_probe) noexcept {
  const auto& ax = config_.axes[a];
  const std::uint16_t in = banks[ax.inputs_bank & 1u];
  Axis& s = axes_[a];
  const bool home = ax.home_bit && (in & ax.home_bit);
  if (s.last_home && !home) s.release_count = s.count;
  s.last_home = home;
  bool index = false;
  if (ax.index_pitch_mm > 0) {
    auto pitch = static_cast<std::int64_t>(std::llround(ax.index_pitch_mm / ax.position_unit_mm));
    auto width = std::max<std::int64_t>(1, std::llround(ax.index_width_mm / ax.position_unit_mm));
    index = in_index_window(s.count - s.release_count, pitch, width);
  }
  return input_bits({.limit_neg = ax.limit_neg_bit && (in & ax.limit_neg_bit),
                     .limit_pos = ax.limit_pos_bit && (in & ax.limit_pos_bit),
                     .tip = raw_probe,
                     .home = home,
                     .index = index});
}

// Steps the set point (braking into a closed limit switch) and writes the PID output with
// velocity feed-forward; true when the following error is beyond the axis' maximum.
bool DriveKitDriver::servo_axis(int a, bool lim_neg, bool lim_pos, double dt) noexcept {
  const auto& ax = config_.axes[a];
  Axis& s = axes_[a];
  const double pos = position(a);
  TrapezoidPlanner& p = s.profile;
  s.lim_neg = lim_neg;
  s.lim_pos = lim_pos;
  if (!loops_closed_) {
    p.reset(pos);
    s.integral = s.last_error = 0;
    s.following = false;
    return false;
  }
  if (s.following && !follow_fresh_) {  // the path stopped coming (dropped): brake from its velocity
    s.following = false;
    p.stop(ax.max_accel);
  }
  if (s.following) {
    // follow() placed the setpoint for now (the end of the period it was given for).
    if ((p.heading() < 0 && lim_neg) || (p.heading() > 0 && lim_pos)) {
      s.following = false;  // into a closed limit switch: brake as a move() would
      p.stop(ax.max_accel);
    }
  } else {
    p.brake_into_limits(lim_neg, lim_pos, ax.max_accel);
    p.step(dt);
  }
  double e = p.position() - pos;
  s.max_error = std::max(s.max_error, std::abs(e));
  bool following_fault = false;
  if (std::abs(e) > ax.max_following_error) {
    s.faults |= status::kFollowingError;
    following_fault = true;
  }
  double de = dt > 0 ? (e - s.last_error) / dt : 0.0;
  s.last_error = e;
  double u = ax.feed_forward * p.velocity() + ax.kp * e + ax.ki * s.integral + ax.kd * de;
  // Anti-windup: integrate only while the command is not saturated in the error's direction.
  double u_max = config_.mode == 1 ? config_.dac_limit_mv / ax.mv_per_mm_s : ax.max_speed * 1.5;
  if (std::abs(u) < u_max || (u > 0) != (e > 0)) s.integral += e * dt;
  write_command(a, std::clamp(u, -u_max, u_max));
  return following_fault;
}

std::uint32_t DriveKitDriver::axis_status(int a, const MachineState& out) const noexcept {
  const Axis& s = axes_[a];
  const bool done = s.profile.done();
  return status_word({out.input(a, input::kLimitNeg), out.input(a, input::kLimitPos), done, loops_closed_,
                      done && std::abs(s.profile.position() - position(a)) < config_.axes[a].in_position_mm,
                      latch_valid_},
                     s.faults | safety_faults_);
}

bool DriveKitDriver::read_latch(AxisVec& latched) noexcept {
  latched = latched_;
  latch_valid_ = false;
  if (config_.latch_status_port) port_.out16(config_.latch_status_port, 0);  // re-arm the counters' latch
  return true;
}

bool DriveKitDriver::set_loops(bool closed) noexcept {
  bool faulted = safety_faults_ != 0;
  for (const auto& s : axes_) faulted = faulted || (s.faults & status::kFaultMask);
  if (closed && faulted) return true;  // like the card: a faulted axis stays open
  for (int a = 0; a < n(); ++a) {
    axes_[a].profile.reset(position(a));
    axes_[a].integral = axes_[a].last_error = axes_[a].remainder = 0;
    axes_[a].following = false;
    port_.out16(config_.axes[a].command_port, 0);
  }
  outputs_ = static_cast<std::uint16_t>(closed ? (outputs_ | enable_bits()) : (outputs_ & ~enable_bits()));
  port_.out16(config_.outputs_port, outputs_);
  loops_closed_ = closed;
  return true;
}

bool DriveKitDriver::move(const AxisArray<AxisMove>& moves, unsigned axis_mask) noexcept {
  for (int a = 0; a < n(); ++a)
    if ((axis_mask & (1u << a)) && (!std::isfinite(moves[a].target) || !(moves[a].velocity > 0) || !(moves[a].accel > 0)))
      return false;
  if (!loops_closed_) return true;
  for (int a = 0; a < n(); ++a) {
    Axis& s = axes_[a];
    if (axis_mask & (1u << a))
      s.profile.start(moves[a].target, std::min(moves[a].velocity, config_.axes[a].max_speed),
                      std::min(moves[a].accel, config_.axes[a].max_accel));
    else if (s.following)  // a path no longer fed: that axis brakes
      s.profile.stop(config_.axes[a].max_accel);
    s.following = false;  // the profile holds the path's position and velocity: it goes on from there
  }
  return true;
}

// The setpoint is for the end of this period, which is when the next read_state runs the
// PID: it is compared with the counters read then, and its velocity is the feed-forward.
bool DriveKitDriver::follow(const Setpoint& sp) noexcept {
  for (int a = 0; a < n(); ++a)
    if (!std::isfinite(sp.position[a]) || !std::isfinite(sp.velocity[a])) return false;
  if (!loops_closed_) return true;  // like move(): an open axis ignores it
  for (int a = 0; a < n(); ++a) {
    Axis& s = axes_[a];
    const double v = sp.velocity[a];
    const double d = sp.position[a] - s.profile.position();
    const int heading = v != 0 ? (v > 0 ? 1 : -1) : (d != 0 ? (d > 0 ? 1 : -1) : 0);
    if ((heading < 0 && s.lim_neg) || (heading > 0 && s.lim_pos)) {
      // Into a closed limit switch: this axis brakes as a move() would.
      if (s.following) s.profile.stop(config_.axes[a].max_accel);
      s.following = false;
      continue;
    }
    // At rest on the path when the setpoint neither moves nor changes: in position as today.
    const bool at_rest = sp.velocity[a] == 0 && s.following && sp.position[a] == s.profile.position();
    s.profile.track(sp.position[a], sp.velocity[a], at_rest);
    s.following = true;
  }
  follow_fresh_ = true;
  return true;
}

bool DriveKitDriver::stop(const AxisVec& decel) noexcept {
  for (int a = 0; a < n(); ++a)
    if (!(decel[a] > 0)) return false;
  for (int a = 0; a < n(); ++a) {
    axes_[a].profile.stop(std::min(decel[a], config_.axes[a].max_accel));  // from the path's velocity too
    axes_[a].following = false;
  }
  return true;
}

bool DriveKitDriver::set_position(int axis, double value) noexcept {
  if (axis < 0 || axis >= n() || !std::isfinite(value)) return false;
  double old = position(axis);
  axes_[axis].offset += old - value;
  axes_[axis].profile.shift(value - old);
  return true;
}

bool DriveKitDriver::reset_faults() noexcept {
  safety_faults_ = open_safety_inputs(port_.in16(config_.inputs_port));  // an input still open keeps its fault
  for (auto& s : axes_) s.faults = 0;
  set_loops(false);
  return true;
}

}  // namespace imess::hal
