// "sim-servo-card": the real servo-card driver over a simulated link to the simulated CMM
// (the default backend; the only one whose absolute scales make it referenced at start):
// streamed over a byte-timed serial line ("link": "serial", the default), or request/reply at no cost.
#include "backend_config.hpp"
#include "backend_registry.hpp"
#include "imess/hal/servo_card_driver.hpp"
#include "imess/sim/simulated_cmm.hpp"
#include "json_object.hpp"

namespace imess::app {

namespace {

class SimServoCardMachine final : public Machine {
 public:
  SimServoCardMachine(const DaemonConfig& cfg, const hal::Clock& clock)
      : cmm_(cfg.sim, clock), driver_(cmm_.link(), cfg.card, cmm_.stream()), absolute_(cfg.sim.card.absolute_scales) {}
  void initialise(bool force_reboot) { driver_.initialise(force_reboot); }
  hal::MotionBackend& backend() override { return driver_; }
  hal::SimHooks* sim_hooks() override { return &cmm_.mechanics(); }
  std::string describe() const override {
    const std::string line = cmm_.streamed() ? ", streamed over a simulated serial line" : "";
    return driver_.describe() + " (simulated CMM, " + (absolute_ ? "absolute" : "incremental") + " scales" + line + ")";
  }

 private:
  sim::SimulatedCmm cmm_;
  hal::ServoCardDriver driver_;
  bool absolute_;
};

void load(JsonObject& b, DaemonConfig& cfg) {
  read_card_keys(b, cfg);
  cfg.sim.streamed = b.text("link", "serial", {"serial", "request-reply"}) == "serial";
  cfg.sim.line.baud = b.number("baud", cfg.sim.line.baud, 9600, 10e6);
  cfg.card.stream.baud = cfg.sim.line.baud;
}

std::unique_ptr<Machine> make(const DaemonConfig& cfg, const hal::Clock& clock, bool force_reboot) {
  auto m = std::make_unique<SimServoCardMachine>(cfg, clock);
  m->initialise(force_reboot);
  return m;
}

}  // namespace

const BackendType& sim_servo_card_backend() {
  static const BackendType kType{"sim-servo-card", "the servo card driver on a simulated CMM", true, false, load, nullptr, make, true};
  return kType;
}

}  // namespace imess::app
