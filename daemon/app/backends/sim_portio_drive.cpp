// "sim-portio-drive": the real drive-kit driver on the simulated port space of a CMM with
// DC servo drive kits, which run in virtual kit periods up to each servo call.
#include "backend_config.hpp"
#include "backend_registry.hpp"
#include "imess/hal/drive_kit_driver.hpp"
#include "imess/sim/port_device.hpp"
#include "imess/sim/simulated_port_cmm.hpp"

namespace imess::app {

namespace {

sim::SimulatedDriveKitCmmConfig drive_sim_config(const DaemonConfig& cfg) {
  auto c = simulated_port_cmm_config<sim::SimulatedDriveKitCmmConfig>(cfg);
  c.kits = cfg.ports.drive_sim;
  return c;
}

class SimDriveKitMachine final : public Machine {
 public:
  SimDriveKitMachine(const DaemonConfig& cfg, const hal::Clock& clock)
      : cmm_(drive_sim_config(cfg)),
        driver_(cmm_.port(), clock, cfg.ports.drive),
        pump_(driver_, nullptr, cmm_.kits(), clock, hal::Nanos(static_cast<std::int64_t>(cfg.ports.drive_sim.period_ns))) {}
  void initialise(bool force_reboot) { pump_.initialise(force_reboot); }
  hal::MotionBackend& backend() override { return pump_; }
  hal::SimHooks* sim_hooks() override { return &cmm_.mechanics(); }  // encoders: hand measuring works
  std::string describe() const override { return driver_.describe() + " (simulated drive kits)"; }

 private:
  sim::SimulatedDriveKitCmm cmm_;
  hal::DriveKitDriver driver_;
  sim::BaseTickPump pump_;
};

}  // namespace

const BackendType& sim_portio_drive_backend() {
  static const BackendType kType{"sim-portio-drive", "a simulated CMM with DC servo drive kits on simulated ports", false, true,
                                 [](JsonObject& b, DaemonConfig& cfg) { read_drive_section(b, cfg, true); },
                                 [](DaemonConfig& cfg) { finish_drive_config(cfg, true); },
                                 build_machine<SimDriveKitMachine>};
  return kType;
}

}  // namespace imess::app
