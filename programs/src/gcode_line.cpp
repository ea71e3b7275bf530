// Blanks out of a G-code line, comments kept as written, columns kept for the errors.
#include "gcode_line.hpp"

#include "scanner.hpp"

namespace imess::programs::detail {

CompactLine compact_line(std::string_view s) {
  CompactLine out;
  out.text.reserve(s.size());
  out.columns.reserve(s.size());
  bool in_paren = false, rest_comment = false, first = true;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (!in_paren && !rest_comment) {
      if (is_blank(c)) continue;
      if (first && c == '/') {
        out.block_delete = true;
        first = false;
        continue;
      }
      if (c == '(') in_paren = true;
      else if (c == ';') rest_comment = true;
    } else if (in_paren && c == ')') {
      in_paren = false;
    }
    first = false;
    out.text += c;
    out.columns.push_back(static_cast<int>(i + 1));
  }
  return out;
}

}  // namespace imess::programs::detail
