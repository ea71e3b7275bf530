// Machine: the hardware messd drives — a MotionBackend and, when simulated, the simulator
// behind it. make_machine builds the one the configuration names.
#pragma once
#include <memory>
#include <string>

#include "imess/hal/motion_backend.hpp"

namespace imess::sim {
class StepperMachine;
}

namespace imess::app {

struct DaemonConfig;  // config.hpp

class Machine {
 public:
  virtual ~Machine() = default;
  virtual hal::MotionBackend& backend() = 0;
  virtual hal::SimHooks* sim_hooks() = 0;  // nullptr on real hardware
  virtual std::string describe() const = 0;
  // The simulated step/dir machine behind a simulated parallel port (its step counts, lost
  // steps and timing violations, for tests); nullptr elsewhere.
  virtual sim::StepperMachine* stepper_sim() { return nullptr; }
  // Optional fast thread of a backend with a base-period routine (steppers on a real
  // port). main() starts it after the motion loop and stops it before; returns a line
  // for the log ("" when there is none).
  virtual std::string start_base_thread(bool /*want_realtime*/) { return ""; }
  virtual void stop_base_thread() {}
};

// Builds and initialises the configured machine; throws std::runtime_error naming the
// problem (device missing, firmware, permissions), a ConfigError for settings the backend
// cannot run.
std::unique_ptr<Machine> make_machine(const DaemonConfig& config, const hal::Clock& clock, bool force_reboot);

}  // namespace imess::app
