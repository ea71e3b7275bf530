// Fuzz target: 1996 messdrc text -> DaemonConfig; only ConfigError may leave the reader.
#include <cstddef>
#include <cstdint>
#include <string>

#include "config.hpp"
#include "json_object.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  imess::app::DaemonConfig config;
  try {
    (void)imess::app::load_messdrc_text(std::string(reinterpret_cast<const char*>(data), size), "messdrc", config);
  } catch (const imess::app::ConfigError&) {
  }
  return 0;
}
