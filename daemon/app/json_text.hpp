// JSON text to a document, strictly: duplicate keys, numbers too large for a double, empty
// files and absurd nesting are reported naming the file and key, as every ConfigError is.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace imess::app {

// Deepest nesting of objects and arrays accepted (the real configuration needs 5).
inline constexpr std::size_t kMaxJsonDepth = 32;

// Parses `text` (comments allowed) read from `file`. A number too large for a double
// (1e400) becomes a string holding its text, so the key's reader refuses it with the key's
// accepted range. Throws ConfigError for everything else that is wrong.
nlohmann::json parse_json_text(std::string text, const std::string& file);

}  // namespace imess::app
