// The backend-specific configuration sections: the parallel-port stepper machine and the
// port-I/O drive kit (both real and simulated), read from "backend" in the JSON file into
// DaemonConfig::ports (PortBackendConfig, port_backend_config.hpp).
#pragma once
namespace imess::app {

class JsonObject;
struct DaemonConfig;

// The sections of the stepper (parport) and drive-kit (portio-drive) backends, real and
// simulated; called by their entries in backends/ (backend_registry.hpp).
void read_stepper_section(JsonObject& b, DaemonConfig& cfg, bool simulated);
void read_drive_section(JsonObject& b, DaemonConfig& cfg, bool simulated);
// The servo card's keys, real and simulated: firmware, max_following_error, and the least
// lead of the streamed setpoints (lead_ms).
void read_card_keys(JsonObject& b, DaemonConfig& cfg);
// Derive what follows from the rest of the configuration (axes, motion period, sim).
void finish_stepper_config(DaemonConfig& cfg, bool simulated);
void finish_drive_config(DaemonConfig& cfg, bool simulated);

}  // namespace imess::app
