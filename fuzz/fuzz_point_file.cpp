// Fuzz target: point file text -> plain points, probed points and the column count, or one
// PointFileError; nothing else may escape, and every parsed hit must satisfy the file rules.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "imess/metrology/point_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imess::metrology;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    (void)point_file_columns(text, "fuzz");
  } catch (const PointFileError&) {
  }
  try {
    for (const auto& p : parse_points(text, "fuzz"))
      if (!p.allFinite()) std::abort();
  } catch (const PointFileError&) {
  }
  try {
    for (const auto& h : parse_probed_points(text, "fuzz")) {
      const double len = h.approach.norm();
      if (!h.surface.allFinite() || !(h.radius >= 0.0) || !std::isfinite(h.radius)) std::abort();
      if (len != 0.0 && std::abs(len - 1.0) > 1e-12) std::abort();
      if (len == 0.0 && h.radius != 0.0) std::abort();
    }
  } catch (const PointFileError&) {
  }
  return 0;
}
