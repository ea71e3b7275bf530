// Reading program events: blank-separated words, numbers with from_chars.
#include "prog_events.hpp"

#include <charconv>

namespace imess::messprog {
namespace {

std::vector<std::string_view> words(std::string_view line, std::size_t at_most, std::string_view* rest = nullptr) {
  std::vector<std::string_view> w;
  std::size_t i = 0;
  while (w.size() < at_most) {
    while (i < line.size() && line[i] == ' ') ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ') ++j;
    w.push_back(line.substr(i, j - i));
    i = j;
  }
  if (rest) {
    while (i < line.size() && line[i] == ' ') ++i;
    *rest = line.substr(i);
  }
  return w;
}

template <class T>
bool number(std::string_view s, T& out) {
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc{} && end == s.data() + s.size();
}

std::string_view trimmed(std::string_view line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == '\n' || line.back() == ' ')) line.remove_suffix(1);
  return line;
}

}  // namespace

std::optional<BlockEvent> parse_block(std::string_view line) {
  const auto w = words(trimmed(line), 5);
  if (w.size() != 4 || w[0] != "Block") return std::nullopt;
  BlockEvent b{std::string(w[1]), 0, 0, 0};
  const auto slash = w[3].find('/');
  if (!number(w[2], b.line) || slash == std::string_view::npos || !number(w[3].substr(0, slash), b.index) ||
      !number(w[3].substr(slash + 1), b.total))
    return std::nullopt;
  return b;
}

std::optional<ProgPauseEvent> parse_prog_pause(std::string_view line) {
  // messd sends "ProgPause <name> <line> M0" (docs/protocol.md); the reason word, and any
  // later one, is not needed here.
  const auto w = words(trimmed(line), 3);
  ProgPauseEvent p;
  if (w.size() != 3 || w[0] != "ProgPause" || !number(w[2], p.line)) return std::nullopt;
  p.name = std::string(w[1]);
  return p;
}

std::optional<ProgEndEvent> parse_prog_end(std::string_view line) {
  std::string_view rest;
  const auto w = words(trimmed(line), 4, &rest);
  if (w.size() != 4 || w[0] != "ProgEnd") return std::nullopt;
  ProgEndEvent e;
  e.name = std::string(w[1]);
  if (w[2] == "ok") e.outcome = ProgEndEvent::Outcome::Ok;
  else if (w[2] == "failed") e.outcome = ProgEndEvent::Outcome::Failed;
  else if (w[2] == "aborted") e.outcome = ProgEndEvent::Outcome::Aborted;
  else return std::nullopt;
  if (!number(w[3], e.line)) return std::nullopt;
  e.text = std::string(rest);
  return e;
}

const char* outcome_name(ProgEndEvent::Outcome outcome) {
  switch (outcome) {
    case ProgEndEvent::Outcome::Ok: return "ok";
    case ProgEndEvent::Outcome::Failed: return "failed";
    case ProgEndEvent::Outcome::Aborted: return "aborted";
  }
  return "?";
}

std::string load_summary(const std::vector<std::string>& args) {
  std::string out;
  auto add = [&](const std::string& s) { out += (out.empty() ? "" : ", ") + s; };
  for (std::size_t i = 1; i < args.size(); ++i) {  // args[0] is the name
    const std::string& key = args[i];
    const bool has_value = i + 1 < args.size();
    const std::string value = has_value ? args[i + 1] : "";
    if (key == "Lang" && has_value) add(value);
    else if (key == "Lines" && has_value) add(value + " lines");
    else if (key == "Blocks" && has_value) add(value + " blocks");
    else if (key == "Segments" && has_value) add(value + " segments");
    else if (key == "Length" && has_value) add(value + " mm");
    else if (key == "Time" && has_value) add("about " + value + " s");
    else {
      add(key);
      continue;
    }
    ++i;
  }
  return out;
}

}  // namespace imess::messprog
