// Strict JSON parsing for configuration files: one SAX pass finds duplicate keys, depth and
// overflowing numbers (with the key they belong to), then nlohmann builds the document.
#include "json_text.hpp"

#include <set>
#include <vector>

#include "json_object.hpp"

namespace imess::app {

namespace {

using Json = nlohmann::json;

// Walks the document without building it, knowing at every value the key path it is under.
class StrictnessCheck : public nlohmann::json_sax<Json> {
 public:
  explicit StrictnessCheck(const std::string& file) : file_(file) {}

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(true); }
  bool start_array(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
    auto& f = frames_.back();
    if (!f.keys.insert(k).second)
      throw ConfigError(file_ + ": key '" + path(k) + "' appears twice in the same object; give each key once");
    f.key = k;
    return true;
  }
  bool parse_error(std::size_t position, const std::string& token, const nlohmann::detail::exception& e) override {
    error_position = position;
    error_token = token;
    error_id = e.id;
    error_text = e.what();
    error_path = frames_.empty() ? std::string() : path_of_value();
    return false;
  }

  std::size_t error_position = 0;
  std::string error_token, error_text, error_path;
  int error_id = 0;

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;        // the current key (objects)
    std::size_t index = 0;  // the current element (arrays)
  };

  std::string path(const std::string& last) const {
    std::string p;
    for (std::size_t i = 0; i + 1 < frames_.size(); ++i) p += step(frames_[i], i);
    return p + (p.empty() ? "" : ".") + last;
  }
  std::string step(const Frame& f, std::size_t depth) const {
    if (!f.object) return "[" + std::to_string(f.index) + "]";
    return (depth == 0 ? "" : ".") + f.key;
  }
  std::string path_of_value() const {
    std::string p;
    for (std::size_t i = 0; i < frames_.size(); ++i) p += step(frames_[i], i);
    return p;
  }
  bool value() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return true;
  }
  bool open(bool object) {
    if (frames_.size() >= kMaxJsonDepth)
      throw ConfigError(file_ + ": '" + path_of_value() + "' nests objects and arrays deeper than " +
                        std::to_string(kMaxJsonDepth) + " levels; the configuration needs at most 5");
    frames_.push_back(Frame{object, {}, {}, 0});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return value();
  }

  const std::string& file_;
  std::vector<Frame> frames_;
};

// nlohmann's "[json.exception.parse_error.101] parse error at line 4, column 3: syntax error
// while parsing object key - unexpected '}'; expected string literal" without the library's
// prefix: "at line 4, column 3: syntax error ...".
std::string parse_error_text(const std::string& what) {
  std::string text = what;
  if (auto close = text.find("] "); text.rfind("[json.exception.", 0) == 0 && close != std::string::npos)
    text.erase(0, close + 2);
  if (text.rfind("parse error ", 0) == 0) text.erase(0, 12);
  return text;
}

bool only_blanks(const std::string& text) { return text.find_first_not_of(" \t\r\n") == std::string::npos; }

}  // namespace

Json parse_json_text(std::string text, const std::string& file) {
  if (only_blanks(text)) throw ConfigError(file + ": is empty; a configuration is a JSON object { ... }");
  // Each round replaces one overflowing number by its text as a string; a document has a
  // bounded number of numbers, and each round removes one.
  for (;;) {
    StrictnessCheck check(file);
    if (Json::sax_parse(text, &check, Json::input_format_t::json, true, /*ignore_comments=*/true)) break;
    const auto& tok = check.error_token;
    const std::size_t end = check.error_position;
    if (check.error_id == 406 && !tok.empty() && end >= tok.size() && end <= text.size() &&
        text.compare(end - tok.size(), tok.size(), tok) == 0) {
      text.replace(end - tok.size(), tok.size(), Json(tok).dump());
      continue;
    }
    if (check.error_id == 406)  // not found where expected: still name the key, if any
      throw ConfigError(file + ": key '" + check.error_path + "' holds a number too large for a double ('" + tok +
                        "'); see docs/configuration.md for its range");
    throw ConfigError(file + ": not valid JSON " + parse_error_text(check.error_text));
  }
  try {
    return Json::parse(text, nullptr, true, /*ignore_comments=*/true);
  } catch (const Json::exception& e) {  // the check above passed, so this is not expected
    throw ConfigError(file + ": not valid JSON: " + e.what());
  }
}

}  // namespace imess::app
