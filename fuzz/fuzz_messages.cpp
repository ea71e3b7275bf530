// Fuzz target: the client-side parser of daemon lines (protocol::parse_message), line by line.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "imess/protocol/messages.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  (void)imess::protocol::parse_message(text);  // the whole input as one line
  while (!text.empty()) {
    auto nl = text.find('\n');
    (void)imess::protocol::parse_message(text.substr(0, nl));
    text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
  }
  return 0;
}
