// Strict JSON parsing for configuration files: imess::jsontext's SAX pass (duplicate keys,
// depth, overflowing numbers with their key), its refusals as ConfigError.
#include "json_text.hpp"

#include "imess/jsontext/strict_json.hpp"
#include "json_object.hpp"

namespace imess::app {

namespace {
bool only_blanks(const std::string& text) { return text.find_first_not_of(" \t\r\n") == std::string::npos; }
}  // namespace

nlohmann::json parse_json_text(std::string text, const std::string& file) {
  if (only_blanks(text)) throw ConfigError(file + ": is empty; a configuration is a JSON object { ... }");
  jsontext::Options options;
  options.comments = true;
  options.overflow_as_text = true;  // the key's reader names its range
  options.max_depth = kMaxJsonDepth;
  options.depth_hint = "the configuration needs at most 5";
  try {
    return jsontext::parse_strict(text, file, options);
  } catch (const jsontext::JsonTextError& e) {
    throw ConfigError(e.what());
  }
}

}  // namespace imess::app
