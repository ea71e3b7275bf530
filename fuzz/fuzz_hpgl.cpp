// Fuzz target: HPGL text -> program items or one error; nothing may throw or crash.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "imess/programs/hpgl.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const imess::programs::HpglOptions options;
  const auto t = imess::programs::translate_hpgl(std::string_view(reinterpret_cast<const char*>(data), size), options);
  if (!t.ok) (void)t.error.message();
  for (const auto& item : t.items) (void)imess::programs::describe(item, options.machine);
  return 0;
}
