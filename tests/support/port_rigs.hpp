// Rigs for the port backends in virtual time: the simulated machine behind a private port
// space, the real hal driver on it, the base routine pumped tick by tick (no threads, no
// sleeping), and optionally the MotionCore on top (MotionRig, core_rig.hpp).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core_rig.hpp"
#include "imess/hal/parport_stepper_driver.hpp"
#include "imess/sim/port_device.hpp"
#include "imess/sim/simulated_port_cmm.hpp"

namespace imess::test {

struct StepperRigOptions {
  sim::SimulatedStepperCmmConfig sim;
  hal::ParportStepperConfig driver;
};

// The test stepper machine: 1000 steps/mm, 5 us base period, 1-tick pulses (100 kHz).
inline StepperRigOptions stepper_options(const std::string& pins = "shd-adapter") {
  StepperRigOptions o;
  o.driver.pins = *hal::named_pin_map(pins);
  o.driver.base = 0x378;
  o.driver.base_period_ns = 5000;
  o.driver.step_len_ns = o.driver.step_space_ns = o.driver.dir_setup_ns = o.driver.dir_hold_ns = 2000;
  for (auto& a : o.driver.axes) {
    a.steps_per_mm = 1000;
    a.max_speed = 90;
    a.max_accel = 4000;
  }
  o.driver.axes[2].home_direction = 1;
  o.driver.initial_position = xyz(o.sim.mechanics.start);
  o.sim.port_base = 0x378;
  o.sim.stepper.pins = o.driver.pins;
  o.sim.stepper.base = 0x378;
  o.sim.stepper.steps_per_mm = {1000, 1000, 1000};
  o.sim.stepper.min_step_len_ns = o.sim.stepper.min_step_space_ns = 1000;
  o.sim.stepper.min_dir_setup_ns = o.sim.stepper.min_dir_hold_ns = 1000;
  return o;
}

class StepperRig final : public MotionRig {
 public:
  explicit StepperRig(StepperRigOptions o = stepper_options())
      : options_(o),
        cmm_(o.sim),
        driver_(cmm_.port(), clock_, o.driver),
        pump_(driver_, &driver_, cmm_.stepper(), clock_, driver_.base_period()) {
    pump_.initialise(false);
  }
  hal::MotionBackend& backend() override { return pump_; }
  hal::ParportStepperDriver& driver() { return driver_; }
  sim::StepperMachine& stepper() { return cmm_.stepper(); }
  sim::Mechanics& mechanics() { return cmm_.mechanics(); }
  hal::SharedPortSpace& port() { return cmm_.port(); }
  sim::BaseTickPump& pump() { return pump_; }
  const StepperRigOptions& options() const { return options_; }
  // Servo cycles without the core: read_state as the core would, every kPeriod.
  void servo_cycles(int n) {
    hal::MachineState ms;
    for (int i = 0; i < n; ++i) {
      clock_.advance(kPeriod);
      pump_.read_state(ms);
    }
  }

 private:
  StepperRigOptions options_;
  sim::SimulatedStepperCmm cmm_;
  hal::ParportStepperDriver driver_;
  sim::BaseTickPump pump_;
};

}  // namespace imess::test

namespace imess::test {

struct DriveRigOptions {
  sim::SimulatedDriveKitCmmConfig sim;
  hal::DriveKitConfig driver;
};

// The test drive kits: map B, mode 1, 1 um counts, 20 mm/s per volt, 100 us kit period.
inline DriveRigOptions drive_options(int mode = 1, const std::string& map = "mrm-b") {
  DriveRigOptions o;
  o.driver = *hal::named_drive_kit_map(map);
  o.driver.mode = mode;
  for (int a = 0; a < 3; ++a) {
    auto& ax = o.driver.axes[a];
    ax.position_unit_mm = 0.001;
    ax.mv_per_mm_s = 50;
    ax.kp = 60;
    ax.ki = 100;
    ax.max_following_error = 1.0;
    ax.max_speed = 150;
    ax.max_accel = 4000;
    ax.home_direction = a == 2 ? 1 : -1;
  }
  o.driver.initial_position = o.sim.mechanics.start;
  o.sim.kits.ports = o.driver;
  o.sim.kits.mm_s_per_volt = {20, 20, 20};
  return o;
}

// Drive kits standing at `start` with no limit switches fitted (an axis blocked by its end
// stop then trips the following-error limit).
inline DriveRigOptions drive_options_without_switches(const hal::Vec3& start) {
  auto o = drive_options();
  o.sim.mechanics.start = axes3(start);
  o.driver.initial_position = o.sim.mechanics.start;
  for (auto& ax : o.driver.axes) ax.limit_neg_bit = ax.limit_pos_bit = 0;
  o.sim.kits.ports = o.driver;
  return o;
}

class DriveRig final : public MotionRig {
 public:
  explicit DriveRig(DriveRigOptions o = drive_options())
      : cmm_(o.sim),
        driver_(cmm_.port(), clock_, o.driver),
        pump_(driver_, nullptr, cmm_.kits(), clock_, hal::Nanos(static_cast<std::int64_t>(o.sim.kits.period_ns))) {
    pump_.initialise(false);
  }
  hal::MotionBackend& backend() override { return pump_; }
  hal::DriveKitDriver& driver() { return driver_; }
  sim::DriveKitSim& kits() { return cmm_.kits(); }
  sim::Mechanics& mechanics() { return cmm_.mechanics(); }
  hal::SharedPortSpace& port() { return cmm_.port(); }
  sim::BaseTickPump& pump() { return pump_; }

 private:
  sim::SimulatedDriveKitCmm cmm_;
  hal::DriveKitDriver driver_;
  sim::BaseTickPump pump_;
};

}  // namespace imess::test
