// Fuzz target: bytes -> the frame store's JSON reader (messd's frames file, messcap's and
// messoffs's --frames). Only FrameError may escape; a store that parses comes back unchanged
// through the JSON writer (the numbers round-trip exactly).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "imess/metrology/frame_store.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imess::metrology;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const FrameStore store = parse_frame_store(text, "fuzz.json");
    const FrameStore back = parse_frame_store(to_json(store), "round-trip");
    if (back.size() != store.size()) std::abort();
    for (const auto& [name, f] : store.entries()) {
      const NamedFrame* g = back.find(name);
      if (!g || g->raw != f.raw || g->frame.matrix() != f.frame.matrix()) std::abort();
    }
  } catch (const FrameError&) {
  }
  return 0;
}
