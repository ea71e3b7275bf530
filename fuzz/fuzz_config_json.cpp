// Fuzz target: JSON configuration text -> DaemonConfig, nothing started. The only exception
// allowed out of the loader is ConfigError (anything else would end messd at start-up).
#include <cstddef>
#include <cstdint>
#include <string>

#include "config.hpp"
#include "json_object.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  imess::app::DaemonConfig config;
  try {
    imess::app::load_config_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json", config);
    imess::app::finish_config(config);
  } catch (const imess::app::ConfigError&) {
  }
  return 0;
}
