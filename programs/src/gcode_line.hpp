// A G-code line as LinuxCNC reads it: blanks and tabs outside comments removed (so
// `X 4 0 0 . 5` is X400.5), each remaining character keeping its source column, and the
// block-delete '/' recognised when it is the line's first character.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace imess::programs::detail {

struct CompactLine {
  std::string text;          // the line without blanks outside comments
  std::vector<int> columns;  // 1-based source column of each character of text
  bool block_delete = false; // the line began with '/' (dropped from text)
  int column(std::size_t i) const { return i < columns.size() ? columns[i] : (columns.empty() ? 1 : columns.back() + 1); }
};

CompactLine compact_line(std::string_view source);

}  // namespace imess::programs::detail
