// StepperMachine: a stepper CMM behind the simulated parallel port. Each sample it reads
// the data register, decodes step/dir edges with the configured pin map, checks the power
// stage's timing (minimum pulse width and space, direction setup and hold) and counts every
// violation, moves the axes one step per pulse (Mechanics, position-driven), and writes
// the limit, reference, STOP and probe states into the status register (BUSY inverted as
// by the port hardware).
#pragma once
#include <cstdint>

#include "imess/hal/parport_pins.hpp"
#include "imess/hal/port_io.hpp"
#include "imess/sim/mechanics.hpp"
#include "imess/sim/port_device.hpp"

namespace imess::sim {

struct StepperMachineConfig {
  hal::PinMap pins = *hal::named_pin_map("shd-adapter");
  std::uint16_t base = 0x378;
  hal::AxisArray<double> steps_per_mm{200, 200, 200};
  hal::AxisArray<int> home_direction{-1, -1, 1};  // side of each end/ref switch
  // The power stage's data sheet: minimum times it needs, ns.
  double min_step_len_ns = 2000, min_step_space_ns = 2000, min_dir_setup_ns = 2000, min_dir_hold_ns = 2000;
};

struct StepViolations {
  unsigned long pulse_width = 0, step_space = 0, dir_setup = 0, dir_hold = 0;
  unsigned long total() const noexcept { return pulse_width + step_space + dir_setup + dir_hold; }
};

class StepperMachine final : public PortDevice {
 public:
  StepperMachine(StepperMachineConfig config, Mechanics& machine, hal::PortIo& port);

  // Samples the port at time t (ns, increasing): decode, move, feed the inputs back.
  void sample(std::int64_t t_ns) noexcept override;
  // The STOP button (pin mapped to "stop").
  void set_stop(bool pressed) noexcept { stop_ = pressed; }

  std::int64_t steps(int axis) const noexcept { return axes_[axis].count; }
  unsigned long lost_steps(int axis) const noexcept { return axes_[axis].lost; }  // stalled at a hard stop
  unsigned long edges() const noexcept { return edges_; }
  const StepViolations& violations() const noexcept { return violations_; }
  Mechanics& machine() noexcept { return machine_; }
  std::uint8_t status_register() const noexcept { return last_status_; }

 private:
  struct Axis {
    std::int64_t count = 0;
    double origin = 0;  // carriage position at count 0
    bool step = false, dir = false, seen = false;
    std::int64_t rise = INT64_MIN / 2, fall = INT64_MIN / 2, dir_change = INT64_MIN / 2;
    unsigned long lost = 0;
  };
  std::uint8_t status_byte() const noexcept;

  StepperMachineConfig config_;
  Mechanics& machine_;
  hal::PortIo& port_;
  hal::CompiledPins pins_;
  hal::AxisArray<Axis> axes_{};
  StepViolations violations_;
  std::int64_t last_move_t_ = 0;
  bool started_ = false, stop_ = false;
  unsigned long edges_ = 0;
  std::uint8_t last_status_ = 0;
};

}  // namespace imess::sim
