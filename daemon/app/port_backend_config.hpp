// PortBackendConfig: the settings of the port backends (parallel-port steppers and the
// port-I/O drive kits, real and simulated) as DaemonConfig holds them; read by backend_config.
#pragma once
#include "imess/hal/drive_kit_driver.hpp"
#include "imess/hal/parport_stepper_driver.hpp"
#include "imess/hal/port_io.hpp"
#include "imess/sim/drive_kit_sim.hpp"
#include "imess/sim/stepper_machine.hpp"

namespace imess::app {

struct PortBackendConfig {
  hal::PortIoConfig port_io;
  hal::ParportStepperConfig stepper;
  sim::StepperMachineConfig stepper_sim;  // the simulated power stage's minimum timing
  hal::DriveKitConfig drive = *hal::named_drive_kit_map("mrm-b");
  sim::DriveKitSimConfig drive_sim;       // the simulated kits' speed constants and period
  bool initial_position_set = false;
};

}  // namespace imess::app
