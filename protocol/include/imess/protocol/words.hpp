// Words on the wire: a line's words, and their comparison (verbs and parameter names are
// case-insensitive ASCII).
#pragma once
#include <cctype>
#include <string_view>
#include <vector>

namespace imess::protocol {

inline bool iequals(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// The words of a line: the runs of characters between `blanks` (a space by default; messd's
// lines separate words by one space, a client's may use tabs too).
inline std::vector<std::string_view> split_words(std::string_view line, std::string_view blanks = " ") {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && blanks.find(line[i]) != std::string_view::npos) ++i;
    const std::size_t start = i;
    while (i < line.size() && blanks.find(line[i]) == std::string_view::npos) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

}  // namespace imess::protocol
