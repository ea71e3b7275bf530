// make_machine: the registered backend type builds its Machine (backends/<name>.cpp); the
// daemon core sees only MotionBackend (and SimHooks).
#include "machine.hpp"

#include <stdexcept>

#include "backend_registry.hpp"
#include "config.hpp"

namespace imess::app {

std::unique_ptr<Machine> make_machine(const DaemonConfig& cfg, const hal::Clock& clock, bool force_reboot) {
  if (const auto* t = find_backend(cfg.backend)) return t->make(cfg, clock, force_reboot);
  std::string accepted;
  for (const auto& t : backend_types()) accepted += (accepted.empty() ? "" : ", ") + t;
  throw std::runtime_error("backend '" + cfg.backend + "' is not available in this build (accepted: " + accepted + ")");
}

}  // namespace imess::app
