// LineFramer: the I++ DME byte stream -> lines (IPPDME.md §1). A line ends with CR LF; a lone
// CR or LF, or a byte outside 32..126, makes the line illegal (0007); lines are capped.
// Not imess::protocol's framer: that one accepts bare LF and strips telnet, which I++ forbids.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace imess::ippdme {

// Longest line the spec allows, terminator excluded.
inline constexpr std::size_t kMaxLineLength = 65536;

enum class LineFault : unsigned char {
  None,
  IllegalCharacter,  // a byte outside 32..126, a CR not followed by LF, or an LF without CR
  TooLong,           // longer than the cap; text holds its first bytes only
};

struct FramedLine {
  std::string_view text;  // without the CR LF; valid until the next feed()
  LineFault fault = LineFault::None;
};

class LineFramer {
 public:
  explicit LineFramer(std::size_t max_length = kMaxLineLength) : max_(max_length) {}

  // Feeds bytes; calls on_line(const FramedLine&) for each complete line, in order. An LF
  // always ends a line (with or without its CR), so one bad line never swallows the next.
  template <class OnLine>
  void feed(std::string_view bytes, OnLine&& on_line) {
    for (char c : bytes)
      if (take(static_cast<unsigned char>(c))) {
        on_line(FramedLine{line_, fault_});
        line_.clear();
        fault_ = LineFault::None;
      }
  }

  // Bytes held of an unfinished line (never more than the cap plus one).
  std::size_t pending() const { return line_.size(); }

 private:
  bool take(unsigned char c);  // true when c completed a line
  void keep(unsigned char c);
  void mark(LineFault f);

  std::size_t max_;
  std::string line_;
  LineFault fault_ = LineFault::None;
  bool cr_ = false;  // the previous byte was a CR
};

}  // namespace imess::ippdme
