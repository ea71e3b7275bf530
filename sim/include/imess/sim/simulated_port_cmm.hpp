// SimulatedStepperCmm: the whole simulated stepper CMM as the daemon sees it — the
// mechanics and workpiece, a port space (shared file or private) and the stepper machine
// on it. Hand port() to a hal::ParportStepperDriver, then pump both with BaseTickPump.
#pragma once
#include <memory>
#include <string>

#include "imess/hal/port_io.hpp"
#include "imess/sim/mechanics.hpp"
#include "imess/sim/stepper_machine.hpp"

namespace imess::sim {

struct SimulatedStepperCmmConfig {
  MechanicsConfig mechanics;
  Scene scene = default_scene();
  StepperMachineConfig stepper;
  std::string port_file;          // "" = private to the process
  std::uint16_t port_base = 0x300;  // first port of the simulated space
  int port_count = hal::SharedPortSpace::kDefaultCount;
};

class SimulatedStepperCmm {
 public:
  explicit SimulatedStepperCmm(const SimulatedStepperCmmConfig& c)
      : mechanics_(c.mechanics, c.scene),
        ports_(c.port_file, c.port_base, c.port_count),
        stepper_(c.stepper, mechanics_, ports_) {}
  SimulatedStepperCmm(const SimulatedStepperCmm&) = delete;
  SimulatedStepperCmm& operator=(const SimulatedStepperCmm&) = delete;

  hal::SharedPortSpace& port() noexcept { return ports_; }
  Mechanics& mechanics() noexcept { return mechanics_; }
  StepperMachine& stepper() noexcept { return stepper_; }

 private:
  Mechanics mechanics_;
  hal::SharedPortSpace ports_;
  StepperMachine stepper_;
};

}  // namespace imess::sim

#include "imess/sim/drive_kit_sim.hpp"

namespace imess::sim {

struct SimulatedDriveKitCmmConfig {
  MechanicsConfig mechanics;
  Scene scene = default_scene();
  DriveKitSimConfig kits;
  std::string port_file;
  std::uint16_t port_base = 0x300;
  int port_count = hal::SharedPortSpace::kDefaultCount;
};

// The simulated CMM with DC servo drive kits on the port space. Hand port() to a
// hal::DriveKitDriver and pump the kits with BaseTickPump (no base routine, the kits' period).
class SimulatedDriveKitCmm {
 public:
  explicit SimulatedDriveKitCmm(const SimulatedDriveKitCmmConfig& c)
      : mechanics_(c.mechanics, c.scene), ports_(c.port_file, c.port_base, c.port_count), kits_(c.kits, mechanics_, ports_) {}
  SimulatedDriveKitCmm(const SimulatedDriveKitCmm&) = delete;
  SimulatedDriveKitCmm& operator=(const SimulatedDriveKitCmm&) = delete;

  hal::SharedPortSpace& port() noexcept { return ports_; }
  Mechanics& mechanics() noexcept { return mechanics_; }
  DriveKitSim& kits() noexcept { return kits_; }

 private:
  Mechanics mechanics_;
  hal::SharedPortSpace ports_;
  DriveKitSim kits_;
};

}  // namespace imess::sim
