// "sim-parport": the real step/dir driver writing the simulated port space of a simulated
// stepper CMM; base routine and stepper machine in lock-step virtual base periods.
#include "backend_config.hpp"
#include "backend_registry.hpp"
#include "imess/hal/parport_stepper_driver.hpp"
#include "imess/sim/port_device.hpp"
#include "imess/sim/simulated_port_cmm.hpp"

namespace imess::app {

namespace {

sim::SimulatedStepperCmmConfig stepper_sim_config(const DaemonConfig& cfg) {
  auto c = simulated_port_cmm_config<sim::SimulatedStepperCmmConfig>(cfg);
  c.stepper = cfg.ports.stepper_sim;
  return c;
}

class SimParportMachine final : public Machine {
 public:
  SimParportMachine(const DaemonConfig& cfg, const hal::Clock& clock)
      : cmm_(stepper_sim_config(cfg)),
        driver_(cmm_.port(), clock, cfg.ports.stepper),
        pump_(driver_, &driver_, cmm_.stepper(), clock, driver_.base_period()) {}
  void initialise(bool force_reboot) { pump_.initialise(force_reboot); }
  hal::MotionBackend& backend() override { return pump_; }
  // Steppers hold their position and have no encoders: the carriage cannot be pushed by hand.
  hal::SimHooks* sim_hooks() override { return nullptr; }
  std::string describe() const override { return driver_.describe() + " (simulated stepper CMM)"; }
  sim::StepperMachine* stepper_sim() override { return &cmm_.stepper(); }

 private:
  sim::SimulatedStepperCmm cmm_;
  hal::ParportStepperDriver driver_;
  sim::BaseTickPump pump_;
};

}  // namespace

const BackendType& sim_parport_backend() {
  static const BackendType kType{"sim-parport", "a simulated stepper CMM on a simulated parallel port", false, false,
                                 [](JsonObject& b, DaemonConfig& cfg) { read_stepper_section(b, cfg, true); },
                                 [](DaemonConfig& cfg) { finish_stepper_config(cfg, true); },
                                 build_machine<SimParportMachine>};
  return kType;
}

}  // namespace imess::app
