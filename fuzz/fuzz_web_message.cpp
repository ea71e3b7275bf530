// Fuzz target: a browser's WebSocket message -> command_lines, as messd's web front end reads
// it: every line it makes is one the line protocol's framer keeps whole (printable ASCII, at
// most kMaxLineLength, no line end), else a refusal with a line-protocol code. The same bytes
// as a line from messd -> event_json: one valid JSON message, and an event with fields prints
// back to the very line. A points request (imess::webpoints) is answered with one JSON object
// of its type, Export or Fit.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "imess/protocol/line_framer.hpp"
#include "imess/webjson/web_json.hpp"
#include "imess/webpoints/points_request.hpp"

using namespace imess;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  auto r = webjson::command_lines(bytes);
  if (auto* lines = std::get_if<std::vector<std::string>>(&r)) {
    if (lines->empty()) std::abort();
    for (const auto& line : *lines) {
      if (line.size() > protocol::kMaxLineLength) std::abort();
      for (unsigned char c : line)
        if (c < 32 || c > 126) std::abort();
    }
  } else {
    const auto& refusal = std::get<webjson::Refusal>(r);
    if (refusal.code != 101 && refusal.code != 103 && refusal.code != 104) std::abort();
    if (refusal.text.empty()) std::abort();
  }
  if (auto reply = webpoints::answer_points_message(bytes)) {
    const auto answer = nlohmann::json::parse(*reply, nullptr, false);
    if (answer.is_discarded() || !answer.is_object()) std::abort();
    if (answer["type"] != "Export" && answer["type"] != "Fit") std::abort();
  }
  if (bytes.find('\n') == std::string_view::npos) {  // messd's lines hold no line end
    const auto text = webjson::event_text(bytes);
    const auto event = nlohmann::json::parse(text, nullptr, false);
    if (event.is_discarded() || !event.is_object()) std::abort();
    if (event["type"] != "Data" && webjson::event_line(event) != bytes) std::abort();
  }
  return 0;
}
