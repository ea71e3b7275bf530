// The backend-specific configuration sections: the parallel-port stepper machine and the
// port-I/O drive kit (both real and simulated), read from "backend" in the JSON file.
#pragma once
#include <string>

#include "imess/hal/drive_kit_driver.hpp"
#include "imess/hal/parport_stepper_driver.hpp"
#include "imess/hal/port_io.hpp"
#include "imess/sim/drive_kit_sim.hpp"
#include "imess/sim/stepper_machine.hpp"

namespace imess::app {

class JsonObject;
struct DaemonConfig;

struct PortBackendConfig {
  hal::PortIoConfig port_io;
  hal::ParportStepperConfig stepper;
  sim::StepperMachineConfig stepper_sim;  // the simulated power stage's minimum timing
  hal::DriveKitConfig drive = *hal::named_drive_kit_map("mrm-b");
  sim::DriveKitSimConfig drive_sim;       // the simulated kits' speed constants and period
  bool initial_position_set = false;
};

// The sections of the stepper (parport) and drive-kit (portio-drive) backends, real and
// simulated; called by their entries in backends/ (backend_registry.hpp).
void read_stepper_section(JsonObject& b, DaemonConfig& cfg, bool simulated);
void read_drive_section(JsonObject& b, DaemonConfig& cfg, bool simulated);
// Derive what follows from the rest of the configuration (axes, motion period, sim).
void finish_stepper_config(DaemonConfig& cfg, bool simulated);
void finish_drive_config(DaemonConfig& cfg, bool simulated);

}  // namespace imess::app
