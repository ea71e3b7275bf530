// One Machine per backend type; the daemon core sees only MotionBackend (and SimHooks).
#include "machine.hpp"

#include <stdexcept>

#include "imess/hal/servo_card_driver.hpp"
#include "imess/sim/simulated_cmm.hpp"

namespace imess::app {

namespace {

// The simulated CMM behind the emulated servo card: the real driver over a simulated link.
class SimServoCardMachine final : public Machine {
 public:
  SimServoCardMachine(const DaemonConfig& cfg, const hal::Clock& clock)
      : cmm_(cfg.sim, clock), driver_(cmm_.link(), cfg.card), absolute_(cfg.sim.card.absolute_scales) {}
  void initialise(bool force_reboot) { driver_.initialise(force_reboot); }
  hal::MotionBackend& backend() override { return driver_; }
  hal::SimHooks* sim_hooks() override { return &cmm_.mechanics(); }
  std::string describe() const override {
    return driver_.describe() + " (simulated CMM, " + (absolute_ ? "absolute" : "incremental") + " scales)";
  }

 private:
  sim::SimulatedCmm cmm_;
  hal::ServoCardDriver driver_;
  bool absolute_;
};

}  // namespace

std::unique_ptr<Machine> make_machine(const DaemonConfig& cfg, const hal::Clock& clock, bool force_reboot) {
  if (cfg.backend == "sim-servo-card") {
    auto m = std::make_unique<SimServoCardMachine>(cfg, clock);
    m->initialise(force_reboot);
    return m;
  }
  throw std::runtime_error("backend '" + cfg.backend + "' is not available in this build (accepted: sim-servo-card)");
}

}  // namespace imess::app
