// ParportStepperDriver: the MotionBackend for stepper machines on a PC parallel port
// (BRIEF §4). Step and dir on the data register, switches on the status register. Servo
// rate (read_state, 1 ms): trapezoid profiles in step units, a target step count and a
// rate per axis for the step generator. Base rate (base_tick, e.g. 5-20 µs): pulse making,
// STOP, and the probe latch captured at the step count of the edge. follow() (a planned
// path, one setpoint per servo period) replaces the trapezoids: LinuxCNC stepgen's position
// mode, the absolute target step count for the period's end and the rate that spreads the
// steps to go evenly over the period. User outputs ("out N" pins): set_output stores the
// level in an atomic; the base routine, the only writer of the data and control registers
// once running, merges it into every write.
#pragma once
#include <atomic>
#include <string>

#include "imess/hal/base_rate.hpp"
#include "imess/hal/motion_backend.hpp"
#include "imess/hal/port_io.hpp"
#include "imess/hal/servo_interval.hpp"
#include "imess/hal/step_generator.hpp"
#include "imess/hal/trapezoid_planner.hpp"

namespace imess::hal {

struct StepAxisConfig {
  double steps_per_mm = 200;   // BRIEF §4: 200/200/200
  double max_speed = 25;       // mm/s
  double max_accel = 500;      // mm/s²
  double index_pitch_mm = 5;   // a synthesised index every pitch (0: none)
  double index_width_mm = 0.04;
  int home_direction = -1;     // side of an end/ref switch: it reads as that limit too
};

struct ParportStepperConfig {
  PinMap pins = *named_pin_map("shd-adapter");
  std::uint16_t base = 0x378;          // data register; status base+1, control base+2
  double base_period_ns = 20000;       // pulse-making period
  double servo_period_ns = 1'000'000;  // the motion loop period the rates are planned for
  double step_len_ns = 5000, step_space_ns = 5000, dir_setup_ns = 5000, dir_hold_ns = 5000;
  AxisArray<StepAxisConfig> axes{};
  Vec3 initial_position = Vec3::Zero();  // mm where the machine stands at power-on
  bool tip_reversed = false;              // probe opens on contact
};

class ParportStepperDriver final : public MotionBackend, public BaseRateDriver {
 public:
  // Throws std::invalid_argument when the configuration cannot work (pin map, a speed the
  // pulse timing cannot reach).
  ParportStepperDriver(PortIo& port, const Clock& clock, ParportStepperConfig config);

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
  // The pin map's "out 1".."out N". The level reaches the pin at the next base tick; it is
  // kept across loops open/closed, STOP and Reset (off only until first switched on).
  int output_count() const noexcept override { return pins_.output_count; }
  bool set_output(int number, bool on) noexcept override;
  bool output_on(int number) const noexcept override;

  void base_tick() noexcept override;
  Nanos base_period() const noexcept override { return Nanos(static_cast<std::int64_t>(config_.base_period_ns)); }

  // Highest step rate per axis the pulse timing allows (steps/s), and what limits it.
  double max_step_rate() const noexcept;
  const StepTiming& timing() const noexcept { return gen_.timing(); }
  std::int64_t step_count(int axis) const noexcept { return gen_.count(axis); }
  // Step count for an absolute coordinate: round(mm × steps/mm) + zero offset (BRIEF §4).
  std::int64_t steps_for(int axis, double mm) const noexcept;

 private:
  std::uint16_t data_port() const noexcept { return config_.base; }
  std::uint16_t status_port() const noexcept { return static_cast<std::uint16_t>(config_.base + 1); }
  std::uint16_t control_port() const noexcept { return static_cast<std::uint16_t>(config_.base + 2); }
  // The control register's value with the user outputs active in `outputs`.
  std::uint8_t control_value(std::uint8_t outputs) const noexcept {
    return static_cast<std::uint8_t>(pins_.control_invert ^ pins_.enable_control_mask ^ outputs);
  }
  bool active(std::uint8_t status, std::uint8_t mask) const noexcept {
    return mask != 0 && ((status ^ pins_.status_xor) & mask) != 0;
  }
  // Commands the generator toward target, the steps to go spread over one servo period
  // (path: rounded up and centred, follow()'s position mode).
  void command_period(int axis, std::int64_t target, bool path = false) noexcept;
  // An axis that was following goes back to its profile (braking, or a move from the path's
  // velocity): the servo step read_state skipped while following is made now.
  void leave_following(int axis) noexcept;

  PortIo& port_;
  const Clock& clock_;
  ParportStepperConfig config_;
  CompiledPins pins_{};
  StepGenerator gen_;
  std::uint64_t ticks_per_servo_ = 50;

  // Shared between the base side (writer) and the servo side (reader).
  std::atomic<bool> halted_{false};
  std::atomic<std::uint8_t> status_{0};
  std::atomic<bool> latch_valid_{false};
  AxisArray<std::atomic<std::int64_t>> latched_{};
  AxisArray<std::atomic<std::int64_t>> release_count_{};  // step count where the home switch last opened
  // Servo side (set_output) writes, base side reads: the register bits of the user outputs
  // that are on, before inversion.
  std::atomic<std::uint8_t> output_data_{0}, output_control_{0};
  // Base side only.
  std::uint8_t last_data_ = 0, last_control_ = 0;
  bool last_contact_ = false;
  AxisArray<bool> last_switch_{};
  bool base_started_ = false;

  // Servo side only.
  AxisArray<TrapezoidPlanner> profile_{};
  AxisArray<std::int64_t> zero_{}, commanded_{};
  AxisArray<double> vmax_{}, amax_{};  // steps/s, steps/s²
  AxisArray<std::int64_t> index_pitch_{}, index_width_{};
  bool loops_closed_ = false;
  ServoInterval servo_interval_;
  // Path following (follow()): per axis, and whether a setpoint came since the last read_state.
  AxisArray<bool> following_{};
  bool follow_fresh_ = false;
  AxisArray<bool> lim_neg_{}, lim_pos_{};  // the limit switches as read_state last saw them
};

}  // namespace imess::hal
