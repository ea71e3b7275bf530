// A browser's WebSocket message to MESSD lines. The message is read strictly (one JSON object,
// no duplicate keys, shallow), and every word it makes must be one a line may hold: no control
// character, no line end that would smuggle a second command in, no space inside an argument.
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "imess/jsontext/strict_json.hpp"
#include "imess/protocol/line_framer.hpp"
#include "imess/protocol/words.hpp"
#include "imess/webjson/web_json.hpp"

namespace imess::webjson {
namespace {

constexpr const char* kAccepted =
    "accepted: {\"cmd\":VERB,\"args\":[numbers or words]}, {\"cmd\":\"\"} (keep-alive), {\"line\":TEXT}, "
    "{\"cmd\":\"Upload\",\"args\":[NAME],\"lines\":[TEXT,...]}";

Refusal refuse(std::string what, int code = 101) { return {code, std::move(what) + "; " + kAccepted}; }

// Printable ASCII (and tab within a line), as the line protocol's framer keeps it (docs/protocol.md).
std::optional<Refusal> check_text(std::string_view text, std::string_view what, bool spaces) {
  if (text.size() > protocol::kMaxLineLength) return refuse(std::string(what) + " is longer than " + std::to_string(protocol::kMaxLineLength) + " characters", 103);
  for (unsigned char c : text) {
    if (c == '\t' && spaces) continue;  // a line may hold a tab, as on 1066; an argument is one word
    if (c < 32 || c > 126)
      return refuse(std::string(what) + " holds a control or non-ASCII character (byte " + std::to_string(c) + ")", 104);
    if (c == ' ' && !spaces) return refuse(std::string(what) + " holds a space: each argument is one word");
  }
  return std::nullopt;
}

std::string number_word(const nlohmann::json& v) {
  if (v.is_number_unsigned()) return std::to_string(v.get<std::uint64_t>());
  if (v.is_number_integer()) return std::to_string(v.get<std::int64_t>());
  char buf[64];
  const double d = v.get<double>();
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, d);  // shortest text that reads back to d
  if (ec != std::errc()) std::snprintf(buf, sizeof buf, "%.17g", d), end = buf + std::char_traits<char>::length(buf);
  return std::string(buf, end);
}

}  // namespace

std::variant<std::vector<std::string>, Refusal> command_lines(std::string_view message) {
  if (message.size() > kMaxMessageBytes)
    return refuse("the message is longer than " + std::to_string(kMaxMessageBytes) + " bytes", 103);
  nlohmann::json j;
  try {
    jsontext::Options options;
    options.max_depth = 2;
    options.depth_hint = "a command is an object of words and lists of words";
    j = jsontext::parse_strict(message, "message", options);
  } catch (const std::exception& e) {
    return refuse(std::string("not a JSON command: ") + e.what());
  }
  if (!j.is_object()) return refuse("the message is not a JSON object");
  for (const auto& [key, v] : j.items())
    if (key != "cmd" && key != "args" && key != "line" && key != "lines")
      return refuse("unknown key \"" + key + "\"");
  const bool has_cmd = j.contains("cmd"), has_line = j.contains("line");
  if (has_cmd == has_line) return refuse(has_cmd ? "both \"cmd\" and \"line\"" : "neither \"cmd\" nor \"line\"");
  std::vector<std::string> lines;
  if (has_line) {
    if (j.contains("args") || j.contains("lines")) return refuse("\"line\" goes alone");
    if (!j["line"].is_string()) return refuse("\"line\" is not a string");
    const auto& text = j["line"].get_ref<const std::string&>();
    if (auto bad = check_text(text, "\"line\"", true)) return *bad;
    lines.push_back(text);
    return lines;
  }
  if (!j["cmd"].is_string()) return refuse("\"cmd\" is not a string");
  const auto& verb = j["cmd"].get_ref<const std::string&>();
  for (unsigned char c : verb)
    if (!std::isalnum(c)) return refuse("\"cmd\" \"" + verb.substr(0, 40) + "\" is not one word of letters and digits");
  if (verb.empty()) {
    if (j.contains("args") || j.contains("lines")) return refuse("the keep-alive {\"cmd\":\"\"} goes alone");
    lines.emplace_back();  // the blank line: the dead-man's keep-alive
    return lines;
  }
  std::string line = verb;
  if (j.contains("args")) {
    const auto& args = j["args"];
    if (!args.is_array()) return refuse("\"args\" is not a list");
    for (const auto& a : args) {
      std::string w;
      if (a.is_number()) {
        w = number_word(a);
      } else if (a.is_string()) {
        w = a.get<std::string>();
        if (w.empty()) return refuse("an argument is an empty string");
        if (auto bad = check_text(w, "an argument", false)) return *bad;
      } else {
        return refuse("an argument is neither a number nor a string");
      }
      line += ' ' + w;
    }
  }
  if (auto bad = check_text(line, "the command", true)) return *bad;
  lines.push_back(std::move(line));
  if (j.contains("lines")) {
    if (!protocol::iequals(verb, "Upload")) return refuse("\"lines\" goes only with \"cmd\":\"Upload\"");
    const auto& body = j["lines"];
    if (!body.is_array()) return refuse("\"lines\" is not a list");
    for (const auto& l : body) {
      if (!l.is_string()) return refuse("a program line is not a string");
      const auto& text = l.get_ref<const std::string&>();
      if (text == ".") return refuse("a program line is \".\", which would end the upload early");
      if (auto bad = check_text(text, "a program line", true)) return *bad;
      lines.push_back(text);
    }
    lines.emplace_back(".");
  }
  return lines;
}

}  // namespace imess::webjson
