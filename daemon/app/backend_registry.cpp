// The table of backends: adding one is a backends/<name>.cpp defining its BackendType and
// one line here (plus the file in CMakeLists.txt). Explicit list, no static registration.
#include "backend_registry.hpp"

namespace imess::app {

// Each defined in backends/<name>.cpp.
const BackendType& sim_servo_card_backend();
const BackendType& servo_card_backend();
const BackendType& sim_parport_backend();
const BackendType& parport_backend();
const BackendType& sim_portio_drive_backend();
const BackendType& portio_drive_backend();

const std::vector<const BackendType*>& backend_registry() {
  static const std::vector<const BackendType*> kAll{&sim_servo_card_backend(), &servo_card_backend(), &sim_parport_backend(), &parport_backend(),
                                                    &sim_portio_drive_backend(), &portio_drive_backend()};
  return kAll;
}

const BackendType* find_backend(const std::string& name) {
  for (const auto* t : backend_registry())
    if (name == t->name) return t;
  return nullptr;
}

const std::vector<std::string>& backend_types() {
  static const std::vector<std::string> kNames = [] {
    std::vector<std::string> names;
    for (const auto* t : backend_registry()) names.emplace_back(t->name);
    return names;
  }();
  return kNames;
}

void load_backend_section(JsonObject& b, DaemonConfig& cfg) {
  if (const auto* t = find_backend(cfg.backend); t && t->load_section) t->load_section(b, cfg);
}

void finish_backend_config(DaemonConfig& cfg) {
  if (const auto* t = find_backend(cfg.backend); t && t->finish) t->finish(cfg);
}

}  // namespace imess::app
