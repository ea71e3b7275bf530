// DriveKitDriver: the MotionBackend for DC servo axes on port I/O (BRIEF §5): per axis a
// command port (DAC millivolts in mode 1, increments per period in mode 2) and a position
// port (signed 16-bit counts, widened here), discrete inputs and outputs. The daemon closes
// the loops: per servo period a trapezoid set point, PID with velocity feed-forward and
// anti-windup, following-error watch. Normally-closed safety inputs stop everything.
// follow() (a planned path, one setpoint per servo period) replaces the trapezoid's set
// point and velocity feed-forward in that same PID step, in both kit modes.
#pragma once
#include <array>
#include <optional>
#include <string_view>
#include <string>

#include "imess/hal/motion_backend.hpp"
#include "imess/hal/port_io.hpp"
#include "imess/hal/servo_interval.hpp"
#include "imess/hal/trapezoid_planner.hpp"

namespace imess::hal {

struct DriveKitAxisConfig {
  std::uint16_t command_port = 0x306, position_port = 0x30B;
  std::uint16_t latch_port = 0;            // counter latch on the probe edge; 0: sample the probe at the servo rate
  double position_unit_mm = 0.1;           // one count on the position port (BRIEF: 0.1 mm)
  double mv_per_mm_s = 50;                 // mode 1: DAC millivolts per mm/s (the drive's speed constant)
  double kp = 60;                          // mm/s per mm of following error
  double ki = 0;                           // mm/s per mm·s
  double kd = 0;                           // mm/s per mm/s of error change
  double feed_forward = 1.0;               // fraction of the set-point velocity fed forward
  double max_following_error = 1.0;        // mm
  double in_position_mm = 0.005;
  double max_speed = 150, max_accel = 3000;  // mm/s, mm/s²
  double index_pitch_mm = 5, index_width_mm = 0.04;  // synthesised index (0: none)
  int home_direction = -1;
  std::uint16_t limit_neg_bit = 0, limit_pos_bit = 0, home_bit = 0;  // in the inputs port of its bank
  std::uint8_t inputs_bank = 0;            // 0: inputs_port, 1: inputs2_port
  std::uint16_t enable_bit = 0;            // amplifier enable in the outputs port
};

// One bit of a 16-bit output port.
struct PortBit {
  std::uint16_t port = 0;
  std::uint16_t mask = 0;  // a single bit
};
inline constexpr int kMaxDriveKitOutputs = 8;

struct DriveKitConfig {
  int mode = 1;                         // 1: DAC mV; 2: increments per period, kit writes 0 back when taken
  std::uint16_t sync_port = 0x300;      // strobe written after each DAC update (0: none)
  std::uint16_t inputs_port = 0x304, outputs_port = 0x303;
  std::uint16_t inputs2_port = 0;       // the switches of axes 4..9 (0: none; BRIEF's kits stop at 3)
  std::uint16_t latch_status_port = 0;  // bit 0 set by the counters when they latched; written 0 to re-arm
  std::uint16_t probe_bit = 0x0200;
  std::array<std::uint16_t, 4> safety_bits{0x1000, 0x2000, 0x4000, 0x8000};  // NC, 1 = closed; 0 = not fitted
  std::uint16_t safe_outputs = 0;       // outputs after a trip (everything off)
  // User outputs 1..output_count (set_output): a bit each, in outputs_port (not an enable
  // bit) or another port. All off at initialise() and after a safety trip or following error.
  std::array<PortBit, kMaxDriveKitOutputs> outputs{};
  int output_count = 0;
  double dac_limit_mv = 10000;
  double servo_period_ns = 1'000'000;
  AxisLayout layout;                    // the axes driven: axes[0 .. layout.count)
  AxisArray<DriveKitAxisConfig> axes{};
  AxisVec initial_position = AxisVec::Zero();  // mm / degrees; the encoder's 16 bits are placed nearest to it
  bool tip_reversed = false;
};

// The two port maps of the MRM manual (BRIEF §5) for `count` axes (1..9) on consecutive
// slots (shown for three; the arm's X Y C U1 U2 are five: command 0x301-0x305, position
// 0x306-0x30A in map A):
// "mrm-a": sync 0x300, command 0x301.., position 0x306.. (+ ours: inputs 0x30B, outputs
//          0x30C, counter latches 0x30D.., then the latch status, then inputs 2);
// "mrm-b": strobe 0x300, outputs 0x303 (0x302 bit 0 = gripper, unused), inputs 0x304,
//          DAC 0x306.., position 0x30B.. (+ ours: latches 0x310.., then status, inputs 2).
// Three axes: latch status 0x310 (a) / 0x313 (b). Inputs: axis 1..3 limit-/limit+/home
// 0x0001/0x0002/0x0004, 0x0008/0x0010/0x0020, 0x0040/0x0080/0x0100, probe 0x0200, safety
// 0x1000-0x8000; axes 4..8 the same pattern in inputs 2 (axis 9: no switches); enables
// 1 << axis. The port ranges must not overlap: map B's positions reach its latches past 5.
// User outputs: map B 1..8 = 0x302 bits 0..7 (bit 0 the manual's gripper); map A (where
// 0x302 is a command port) 1..7 = outputs port 0x30C bits 9..15, above the enables.
std::optional<DriveKitConfig> named_drive_kit_map(std::string_view name, int count = 3);
// Throws std::invalid_argument naming the output ("output 2 (port 0x30C bit 1) ...") when
// the user outputs cannot work: not one bit, an amplifier enable, a port the kit reads or
// commands through (inputs, sync, latches, an axis' command or position port), one bit twice.
void validate_drive_kit_outputs(const DriveKitConfig& config);

class DriveKitDriver final : public MotionBackend {
 public:
  DriveKitDriver(PortIo& port, const Clock& clock, DriveKitConfig config);

  void initialise(bool force_reboot) override;
  std::string describe() const override;

  bool read_state(MachineState& out) noexcept override;
  bool read_latch(AxisVec& latched) noexcept override;
  bool set_loops(bool closed) noexcept override;
  bool move(const AxisArray<AxisMove>& moves, unsigned axis_mask) noexcept override;
  bool follow(const Setpoint& sp) noexcept override;
  bool stop(const AxisVec& decel) noexcept override;
  bool set_position(int axis, double value) noexcept override;
  bool reset_faults() noexcept override;
  // The configured user outputs (DriveKitConfig::outputs): read-modify-write of the port's
  // shadow word. Switching one on is refused (false) while a safety input fault is latched.
  int output_count() const noexcept override { return config_.output_count; }
  bool set_output(int number, bool on) noexcept override;
  bool output_on(int number) const noexcept override;

  double max_following_error_seen(int axis) const noexcept { return axes_[axis].max_error; }
  unsigned long handshake_misses() const noexcept { return handshake_misses_; }
  std::int64_t counts(int axis) const noexcept { return axes_[axis].count; }

 private:
  struct Axis {
    TrapezoidPlanner profile;
    std::int64_t count = 0;           // widened position counts
    std::uint16_t last_raw = 0;
    double offset = 0;                // mm: position = count·unit − offset
    double integral = 0, last_error = 0, max_error = 0, remainder = 0;
    std::int64_t release_count = 0;
    bool last_home = false;
    std::uint32_t faults = 0;
    bool following = false;           // the profile holds a planned path's setpoint (follow())
    bool lim_neg = false, lim_pos = false;  // the limit switches as read_state last saw them
  };
  double position(int a) const noexcept;
  void write_command(int a, double velocity) noexcept;
  // Commands zero, loops open, the outputs port = `outputs` less the user outputs, every
  // user output off.
  void safe_state(std::uint16_t outputs) noexcept;
  void user_outputs_off() noexcept;
  std::uint16_t& shadow(int output) noexcept;
  std::uint16_t enable_bits() const noexcept;
  // The steps of read_state, in their order.
  std::uint32_t open_safety_inputs(std::uint16_t in) const noexcept;
  void trip_safety_inputs(std::uint16_t in) noexcept;
  void widen_counters() noexcept;
  void latch_probe(bool contact) noexcept;
  std::uint8_t sample_inputs(int a, const std::array<std::uint16_t, 2>& in, bool raw_probe) noexcept;
  int n() const noexcept { return config_.layout.count; }
  bool servo_axis(int a, bool lim_neg, bool lim_pos, double dt) noexcept;
  std::uint32_t axis_status(int a, const MachineState& out) const noexcept;

  PortIo& port_;
  const Clock& clock_;
  DriveKitConfig config_;
  AxisArray<Axis> axes_{};
  bool loops_closed_ = false, latch_valid_ = false, last_contact_ = false;
  AxisVec latched_ = AxisVec::Zero();
  ServoInterval servo_interval_;
  std::uint16_t strobe_ = 0, outputs_ = 0;  // outputs_: the outputs port's word as written
  // The words written to the other ports that carry user outputs (one per port, in
  // shadow_ports_); per output its shadow slot, -1: the outputs port (outputs_).
  std::array<std::uint16_t, kMaxDriveKitOutputs> shadow_ports_{}, shadow_words_{};
  std::array<std::int8_t, kMaxDriveKitOutputs> output_slot_{};
  std::uint16_t user_bits_on_outputs_port_ = 0;
  int shadow_count_ = 0;
  std::uint32_t safety_faults_ = 0;
  unsigned long handshake_misses_ = 0;
  bool follow_fresh_ = false;  // a setpoint came since the last read_state
};

}  // namespace imess::hal
