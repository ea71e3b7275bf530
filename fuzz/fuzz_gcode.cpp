// Fuzz target: G-code text -> program items or one error; nothing may throw or crash, and
// every item must describe itself.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "imess/programs/gcode.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  imess::programs::GcodeOptions options;
  options.spindle_output = 1;
  options.digital_output_count = 4;
  const auto t = imess::programs::translate_gcode(std::string_view(reinterpret_cast<const char*>(data), size), options);
  if (!t.ok) (void)t.error.message();
  for (const auto& item : t.items) (void)imess::programs::describe(item, options.machine);
  return 0;
}
