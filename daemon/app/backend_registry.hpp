// The backend registry: one BackendType per "backend.type" value (name, description, section
// loader, factory), each defined in backends/<name>.cpp and listed once in backend_registry.cpp.
#pragma once
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "config.hpp"
#include "json_object.hpp"  // ConfigError
#include "machine.hpp"

namespace imess::app {

struct BackendType {
  const char* name;         // the "backend.type" value
  const char* description;  // one line for people
  bool absolute_scales;     // referenced at start when sim.absolute_scales is set
  bool any_axes;            // drives the axes of axes.letters (else exactly X Y Z)
  // Reads its keys of "backend" (type and tip_reversed already read); nullptr: none.
  void (*load_section)(JsonObject& backend, DaemonConfig& cfg);
  // Derives its settings from the rest of the configuration (axes, period, sim); nullptr: none.
  void (*finish)(DaemonConfig& cfg);
  // Builds and initialises the machine; throws std::runtime_error naming the problem.
  std::unique_ptr<Machine> (*make)(const DaemonConfig& cfg, const hal::Clock& clock, bool force_reboot);
  // Output 1 powers the probe (the servo card's "measuring instrument on"): without an
  // "outputs" section the machine has the output "probe", on at start.
  bool probe_power_output = false;
};

// Every backend of this build, in the order error messages list them.
const std::vector<const BackendType*>& backend_registry();
const BackendType* find_backend(const std::string& name);  // nullptr when unknown
const std::vector<std::string>& backend_types();           // the names
// The registered entry's section loader and finisher (nothing for an unknown name).
void load_backend_section(JsonObject& b, DaemonConfig& cfg);
void finish_backend_config(DaemonConfig& cfg);

// The part every simulated port-space CMM takes from the configuration: the mechanics, the
// workpiece and where its simulated port registers live.
template <class SimConfig>
SimConfig simulated_port_cmm_config(const DaemonConfig& cfg) {
  SimConfig c;
  c.mechanics = cfg.sim.mechanics;
  c.scene = cfg.sim.scene;
  c.port_file = cfg.ports.port_io.file;
  c.port_base = cfg.ports.port_io.base;
  c.port_count = cfg.ports.port_io.count;
  return c;
}

// The usual factory: construct, then initialise. A std::invalid_argument from a constructor
// is a configuration the driver cannot run (keys that contradict each other): a ConfigError
// naming the backend, so messd exits 2 as for any bad configuration.
template <class M>
std::unique_ptr<Machine> build_machine(const DaemonConfig& cfg, const hal::Clock& clock, bool force_reboot) {
  std::unique_ptr<M> m;
  try {
    m = std::make_unique<M>(cfg, clock);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(cfg.backend + ": " + e.what());
  }
  m->initialise(force_reboot);
  return m;
}

}  // namespace imess::app
