// Strict JSON parsing for every reader: one SAX pass finds duplicate keys, depth and
// overflowing numbers (with the key they belong to), then nlohmann builds the document.
#include "imess/jsontext/strict_json.hpp"

#include <set>
#include <vector>

namespace imess::jsontext {

namespace {

using Json = nlohmann::json;

// Walks the document without building it, knowing at every value the key path it is under.
class StrictnessCheck : public nlohmann::json_sax<Json> {
 public:
  StrictnessCheck(std::string_view source, const Options& options) : source_(source), options_(options) {}

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
      throw JsonTextError(std::string(source_) + ": key '" + path(k) + "' appears twice in the same object; give each key once");
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
    if (frames_.size() >= options_.max_depth)
      throw JsonTextError(std::string(source_) + ": '" + path_of_value() + "' nests objects and arrays deeper than " +
                          std::to_string(options_.max_depth) + " levels" +
                          (options_.depth_hint.empty() ? std::string() : "; " + std::string(options_.depth_hint)));
    frames_.push_back(Frame{object, {}, {}, 0});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return value();
  }

  std::string_view source_;
  const Options& options_;
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

std::string too_large(std::string_view source, const std::string& path, const std::string& token) {
  const std::string where = path.empty() ? std::string("the document") : "key '" + path + "'";
  return std::string(source) + ": " + where + " holds a number too large for a double ('" + token +
         "'); numbers from -1.7976931348623157e308 to 1.7976931348623157e308 are accepted";
}

}  // namespace

Json parse_strict(std::string_view input, std::string_view source, const Options& options) {
  std::string text(input);
  // With overflow_as_text, each round replaces one overflowing number by its text as a
  // string; a document has a bounded number of numbers, and each round removes one.
  for (;;) {
    StrictnessCheck check(source, options);
    if (Json::sax_parse(text, &check, Json::input_format_t::json, true, options.comments)) break;
    const auto& tok = check.error_token;
    const std::size_t end = check.error_position;
    const bool found = !tok.empty() && end >= tok.size() && end <= text.size() &&
                       text.compare(end - tok.size(), tok.size(), tok) == 0;
    if (check.error_id == 406 && options.overflow_as_text && found) {
      text.replace(end - tok.size(), tok.size(), Json(tok).dump());
      continue;
    }
    if (check.error_id == 406) throw JsonTextError(too_large(source, check.error_path, tok));
    throw JsonTextError(std::string(source) + ": not valid JSON " + parse_error_text(check.error_text));
  }
  try {
    return Json::parse(text, nullptr, true, options.comments);
  } catch (const Json::exception& e) {  // the check above passed, so this is not expected
    throw JsonTextError(std::string(source) + ": not valid JSON: " + e.what());
  }
}

std::optional<nlohmann::json> object_naming(std::string_view message, std::initializer_list<std::string_view> keys,
                                            const Options& options) {
  auto names = [&](std::string_view key) {
    return message.find("\"" + std::string(key) + "\"") != std::string_view::npos;
  };
  bool named = false;
  for (const auto key : keys) named = named || names(key);
  if (!named) return std::nullopt;
  nlohmann::json j;
  try {
    j = parse_strict(message, "message", options);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (!j.is_object()) return std::nullopt;
  for (const auto key : keys)
    if (j.contains(key)) return j;
  return std::nullopt;
}

}  // namespace imess::jsontext
