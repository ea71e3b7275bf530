// set_messdrc_values: rewrites the value word of the settings' lines, appends the missing ones.
#include "messdrc_edit.hpp"

#include <algorithm>
#include <map>

namespace imess::messcap {
namespace {

constexpr std::string_view kBlank = " \t";

// The line with the value word after the key replaced; what follows the value keeps its column.
std::string with_value(const std::string& line, std::size_t key_end, const std::string& value) {
  const std::size_t value_begin = line.find_first_not_of(kBlank, key_end);
  const bool has_value = value_begin != std::string::npos && line[value_begin] != '#' && line[value_begin] != '\r';
  if (!has_value) {
    const std::string rest = line.substr(key_end);
    const std::size_t keep = rest.find_first_not_of(kBlank);
    return line.substr(0, key_end) + " " + value + (keep == std::string::npos ? "" : "  " + rest.substr(keep));
  }
  std::size_t value_end = line.find_first_of(" \t#\r", value_begin);
  if (value_end == std::string::npos) value_end = line.size();
  std::string rest = line.substr(value_end);
  const std::size_t old_length = value_end - value_begin;
  const std::size_t blanks = rest.find_first_not_of(kBlank) == std::string::npos ? 0 : rest.find_first_not_of(kBlank);
  if (blanks > 0) {  // a comment follows: keep its column when the new value leaves room
    const std::size_t want = old_length + blanks > value.size() ? old_length + blanks - value.size() : 1;
    rest = std::string(std::max<std::size_t>(want, 1), ' ') + rest.substr(blanks);
  }
  return line.substr(0, value_begin) + value + rest;
}

}  // namespace

std::string set_messdrc_values(std::string_view text, const std::vector<RcSetting>& settings, const std::string& source) {
  std::map<std::string, int> first_line;  // key -> the line it is on
  std::vector<bool> done(settings.size(), false);
  std::string out;
  std::size_t pos = 0;
  for (int number = 1; pos < text.size(); ++number) {
    std::size_t end = text.find('\n', pos);
    const bool newline = end != std::string_view::npos;
    if (!newline) end = text.size();
    std::string line(text.substr(pos, end - pos));
    pos = newline ? end + 1 : end;

    const std::size_t key_begin = line.find_first_not_of(kBlank);
    if (key_begin != std::string::npos && line[key_begin] != '#') {
      std::size_t key_end = line.find_first_of(" \t#\r", key_begin);
      if (key_end == std::string::npos) key_end = line.size();
      const std::string key = line.substr(key_begin, key_end - key_begin);
      for (std::size_t s = 0; s < settings.size(); ++s) {
        if (settings[s].key != key) continue;
        if (auto seen = first_line.find(key); seen != first_line.end())
          throw MessdrcEditError(source + ": line " + std::to_string(number) + ": " + key + " is set again (first on line " +
                                 std::to_string(seen->second) + "); messd refuses such a file — remove one of them first");
        first_line[key] = number;
        line = with_value(line, key_end, settings[s].value);
        done[s] = true;
      }
    }
    out += line;
    if (newline) out += '\n';
  }
  if (!out.empty() && out.back() != '\n') out += '\n';
  for (std::size_t s = 0; s < settings.size(); ++s) {
    if (done[s]) continue;
    out += settings[s].key + " " + settings[s].value;
    if (!settings[s].comment.empty()) out += "  # " + settings[s].comment;
    out += '\n';
  }
  return out;
}

}  // namespace imess::messcap
