// Wrapping the jog panel's messages to the terminal: nothing is cut at the right edge.
#include "note_rows.hpp"

#include <algorithm>

namespace imess::messjog {

std::vector<std::string> wrap_message(const std::string& message, int width) {
  const std::size_t w = static_cast<std::size_t>(std::max(width, 8));
  std::vector<std::string> rows;
  std::string row;
  auto cap = [&] { return w - (rows.empty() ? 0 : 2); };  // continuation rows are indented
  auto flush = [&] {
    rows.push_back((rows.empty() ? "" : "  ") + row);
    row.clear();
  };
  std::size_t at = 0;
  while (at <= message.size()) {
    std::size_t end = message.find(' ', at);
    if (end == std::string::npos) end = message.size();
    std::string word = message.substr(at, end - at);
    at = end + 1;
    while (word.size() > cap()) {  // longer than any row: broken inside
      if (!row.empty()) flush();
      row = word.substr(0, cap());
      word.erase(0, row.size());
      flush();
    }
    if (word.empty()) continue;
    if (row.empty())
      row = word;
    else if (row.size() + 1 + word.size() <= cap())
      row += " " + word;
    else {
      flush();
      row = word;
    }
  }
  if (!row.empty() || rows.empty()) flush();
  return rows;
}

std::vector<std::string> note_rows(const std::deque<std::string>& notes, int width, int rows) {
  std::vector<std::string> all;
  for (const auto& n : notes) {
    auto wrapped = wrap_message(n, width);
    all.insert(all.end(), wrapped.begin(), wrapped.end());
  }
  const std::size_t keep = static_cast<std::size_t>(std::max(rows, 0));
  if (all.size() > keep) all.erase(all.begin(), all.end() - static_cast<std::ptrdiff_t>(keep));
  return all;
}

}  // namespace imess::messjog
