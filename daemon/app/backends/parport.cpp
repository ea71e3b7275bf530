// "parport": a stepper machine on a real parallel port (x86 ports or ppdev), its base
// routine in its own thread.
#include "backend_config.hpp"
#include "backend_registry.hpp"
#include "base_thread.hpp"
#include "imess/hal/parport_stepper_driver.hpp"

namespace imess::app {

namespace {

class ParportMachine final : public Machine {
 public:
  ParportMachine(const DaemonConfig& cfg, const hal::Clock& clock)
      : port_(hal::make_port_io(cfg.ports.port_io)), driver_(*port_, clock, cfg.ports.stepper), base_(driver_) {}
  void initialise(bool force_reboot) { driver_.initialise(force_reboot); }
  hal::MotionBackend& backend() override { return driver_; }
  hal::SimHooks* sim_hooks() override { return nullptr; }
  std::string describe() const override { return driver_.describe(); }
  std::string start_base_thread(bool want_realtime) override { return base_.start(want_realtime); }
  void stop_base_thread() override { base_.stop(); }

 private:
  std::unique_ptr<hal::PortIo> port_;
  hal::ParportStepperDriver driver_;
  BaseThread base_;
};

}  // namespace

const BackendType& parport_backend() {
  static const BackendType kType{"parport", "a stepper machine on a real parallel port", false, false,
                                 [](JsonObject& b, DaemonConfig& cfg) { read_stepper_section(b, cfg, false); },
                                 [](DaemonConfig& cfg) { finish_stepper_config(cfg, false); },
                                 build_machine<ParportMachine>};
  return kType;
}

}  // namespace imess::app
