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

// Backend types known to this build.
const std::vector<std::string>& backend_types();
bool is_parport(const std::string& type);
bool is_simulated(const std::string& type);
bool is_drive_kit(const std::string& type);
// Reads the keys of the chosen backend type from "backend" (type already read).
void load_backend_section(JsonObject& b, DaemonConfig& cfg);
// Derives what follows from the rest of the configuration (axes, motion period, sim).
void finish_backend_config(DaemonConfig& cfg);

}  // namespace imess::app
