// Fuzz target: client bytes -> LineFramer -> parse_command, as a session reads them. The
// first byte chooses the read size, so lines are split across reads at every place.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "imess/protocol/line_framer.hpp"
#include "imess/protocol/verbs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t chunk = 1 + data[0] % 16;
  std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  imess::protocol::LineFramer framer;
  for (std::size_t at = 0; at < bytes.size(); at += chunk) {
    framer.feed(bytes.substr(at, chunk), [](const imess::protocol::FramedLine& line) {
      // What the framer promises: bounded lines that never hold their terminator.
      if (line.text.size() > imess::protocol::kMaxLineLength || line.text.find('\n') != std::string_view::npos) std::abort();
      if (!line.overlong) (void)imess::protocol::parse_command(line.text);
    });
    if (framer.pending() > imess::protocol::kMaxLineLength) std::abort();
  }
  return 0;
}
