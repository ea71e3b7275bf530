// One Machine per backend type; the daemon core sees only MotionBackend (and SimHooks).
#include "machine.hpp"

#include <stdexcept>

#include "base_thread.hpp"
#include "imess/hal/drive_kit_driver.hpp"
#include "imess/hal/parport_stepper_driver.hpp"
#include "imess/hal/servo_card_driver.hpp"
#include "imess/sim/port_device.hpp"
#include "imess/sim/simulated_cmm.hpp"
#include "imess/sim/simulated_port_cmm.hpp"

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

sim::SimulatedStepperCmmConfig stepper_sim_config(const DaemonConfig& cfg) {
  sim::SimulatedStepperCmmConfig c;
  c.mechanics = cfg.sim.mechanics;
  c.scene = cfg.sim.scene;
  c.stepper = cfg.ports.stepper_sim;
  c.port_file = cfg.ports.port_io.file;
  c.port_base = cfg.ports.port_io.base;
  c.port_count = cfg.ports.port_io.count;
  return c;
}

// The simulated stepper CMM: the real step/dir driver writes the simulated port space; the
// base routine and the stepper machine run in lock-step virtual base periods (BaseTickPump).
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

 private:
  sim::SimulatedStepperCmm cmm_;
  hal::ParportStepperDriver driver_;
  sim::BaseTickPump pump_;
};

// A stepper machine on a real parallel port (x86 ports or ppdev), base routine in its own thread.
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

sim::SimulatedDriveKitCmmConfig drive_sim_config(const DaemonConfig& cfg) {
  sim::SimulatedDriveKitCmmConfig c;
  c.mechanics = cfg.sim.mechanics;
  c.scene = cfg.sim.scene;
  c.kits = cfg.ports.drive_sim;
  c.port_file = cfg.ports.port_io.file;
  c.port_base = cfg.ports.port_io.base;
  c.port_count = cfg.ports.port_io.count;
  return c;
}

// The simulated CMM with DC servo drive kits: the real drive-kit driver on the simulated
// port space; the kits run in virtual kit periods up to each servo call.
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

// Drive kits on real port hardware (DAC and counter cards at x86 port addresses).
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

template <class M>
std::unique_ptr<Machine> build(const DaemonConfig& cfg, const hal::Clock& clock, bool force_reboot) {
  std::unique_ptr<M> m;
  try {
    m = std::make_unique<M>(cfg, clock);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(cfg.backend + ": " + e.what());
  }
  m->initialise(force_reboot);
  return m;
}

}  // namespace

std::unique_ptr<Machine> make_machine(const DaemonConfig& cfg, const hal::Clock& clock, bool force_reboot) {
  if (cfg.backend == "sim-servo-card") {
    auto m = std::make_unique<SimServoCardMachine>(cfg, clock);
    m->initialise(force_reboot);
    return m;
  }
  if (cfg.backend == "sim-parport") return build<SimParportMachine>(cfg, clock, force_reboot);
  if (cfg.backend == "parport") return build<ParportMachine>(cfg, clock, force_reboot);
  if (cfg.backend == "sim-portio-drive") return build<SimDriveKitMachine>(cfg, clock, force_reboot);
  if (cfg.backend == "portio-drive") return build<DriveKitMachine>(cfg, clock, force_reboot);
  std::string accepted;
  for (const auto& t : backend_types()) accepted += (accepted.empty() ? "" : ", ") + t;
  throw std::runtime_error("backend '" + cfg.backend + "' is not available in this build (accepted: " + accepted + ")");
}

}  // namespace imess::app
