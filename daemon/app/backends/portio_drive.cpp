// "portio-drive": DC servo drive kits on real port hardware (DAC and counter cards at x86
// port addresses).
#include "backend_config.hpp"
#include "backend_registry.hpp"
#include "imess/hal/drive_kit_driver.hpp"

namespace imess::app {

namespace {

class DriveKitMachine final : public Machine {
 public:
  DriveKitMachine(const DaemonConfig& cfg, const hal::Clock& clock)
      : port_(hal::make_port_io(cfg.ports.port_io)), driver_(*port_, clock, cfg.ports.drive) {}
  void initialise(bool force_reboot) { driver_.initialise(force_reboot); }
  hal::MotionBackend& backend() override { return driver_; }
  hal::SimHooks* sim_hooks() override { return nullptr; }
  std::string describe() const override { return driver_.describe(); }

 private:
  std::unique_ptr<hal::PortIo> port_;
  hal::DriveKitDriver driver_;
};

}  // namespace

const BackendType& portio_drive_backend() {
  static const BackendType kType{"portio-drive", "DC servo drive kits on real port hardware", false, true,
                                 [](JsonObject& b, DaemonConfig& cfg) { read_drive_section(b, cfg, false); },
                                 [](DaemonConfig& cfg) { finish_drive_config(cfg, false); },
                                 build_machine<DriveKitMachine>};
  return kType;
}

}  // namespace imess::app
