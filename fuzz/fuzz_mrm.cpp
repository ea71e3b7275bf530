// Fuzz target: MRM robot-arm program text -> program items or one error; nothing may throw.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "imess/programs/mrm.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const imess::programs::MrmOptions options;
  const auto t = imess::programs::translate_mrm(std::string_view(reinterpret_cast<const char*>(data), size), options);
  if (!t.ok) (void)t.error.message();
  for (const auto& item : t.items) (void)imess::programs::describe(item, options.machine);
  return 0;
}
