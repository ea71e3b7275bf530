// messprog check's output.
#include "check_report.hpp"

#include <cmath>
#include <cstdio>

#include "number_text.hpp"

namespace imess::messprog {

std::string located_error(std::string_view file, std::string_view message) {
  constexpr std::string_view prefix = "line ";
  if (message.substr(0, prefix.size()) == prefix) {
    const auto rest = message.substr(prefix.size());  // "3:7: kind: ..."
    const auto colon = rest.find(':');
    const auto second = colon == std::string_view::npos ? colon : rest.find(": ", colon + 1);
    if (second != std::string_view::npos) return std::string(file) + ":" + std::string(rest);
  }
  return std::string(file) + ": " + std::string(message);
}

std::string duration_text(double seconds) {
  std::string text = fixed(seconds, 2) + " s";
  if (seconds >= 60) {
    const long total = std::lround(seconds);
    char hms[32];
    std::snprintf(hms, sizeof hms, " (%ld:%02ld:%02ld)", total / 3600, total / 60 % 60, total % 60);
    text += hms;
  }
  return text;
}

std::string check_report(std::string_view file, programs::Language lang, const programs::Check& c,
                         const planner::Machine& machine, std::string_view machine_text) {
  bool rotary = false;
  for (int i = 0; i < machine.count; ++i) rotary = rotary || machine.axes[i].kind == planner::AxisKind::Rotary;
  std::string r = std::string(file) + ": ok (" + programs::language_name(lang) + ")\n";
  r += "lines " + std::to_string(c.lines) + ", blocks " + std::to_string(c.blocks) + ", segments " +
       std::to_string(c.segments) + "\n";
  r += "path length " + fixed(c.length, 3) + " mm: feed " + fixed(c.feed_length, 3) + ", rapid " +
       fixed(c.rapid_length, 3) + ", probe " + fixed(c.probe_length, 3) + "\n";
  if (rotary) r += "  (a move of rotary axes alone counts its degrees)\n";
  r += "estimated time " + duration_text(c.time) +
       " (the planner's estimate: motion profiles, dwells and output holds; a probe as its whole search, M0 as no time)\n";
  r += "machine: " + std::string(machine_text) + "\n";
  if (!c.notes.empty()) {
    r += "accepted without effect, or skipped:\n";
    for (const auto& n : c.notes)
      r += "  " + n.code + " (line " + std::to_string(n.line) + (n.count > 1 ? ", " + std::to_string(n.count) + " times" : "") +
           "): " + n.meaning + "\n";
  }
  if (!c.moves) return r + "bounding box: no motion\n";
  r += "bounding box:\n";
  for (int i = 0; i < machine.count; ++i) {
    const bool deg = machine.axes[i].kind == planner::AxisKind::Rotary;
    char line[128];
    std::snprintf(line, sizeof line, "  %c %12s .. %12s %s\n", machine.axes[i].letter, fixed(c.low[i], 3).c_str(),
                  fixed(c.high[i], 3).c_str(), deg ? "deg" : "mm");
    r += line;
  }
  return r;
}

}  // namespace imess::messprog
