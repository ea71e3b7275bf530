// LineFramer: turns a TCP byte stream into protocol lines. LF ends every line (CRLF and
// telnet's CR NUL too), telnet IAC sequences are stripped and bounded, and the line length
// is capped, so no byte sequence can grow a buffer or silence a session.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace imess::protocol {

// Longest accepted line, terminator excluded (1996: 80). Documented in docs/protocol.md.
inline constexpr std::size_t kMaxLineLength = 200;
// Longest telnet subnegotiation (IAC SB ... IAC SE) skipped; longer ones are abandoned.
inline constexpr std::size_t kMaxSubnegotiation = 64;

// A line as framed. Bytes that make it unacceptable stay in `text`, so the parser answers
// Err 104: a CR or NUL inside the line, and an IAC (0xFF) for a telnet sequence that an LF
// cut short or that ran past kMaxSubnegotiation.
struct FramedLine {
  std::string_view text;  // without the terminator and telnet bytes; valid until the next feed()
  bool overlong = false;  // the line exceeded the limit; text holds its first bytes only
};

class LineFramer {
 public:
  explicit LineFramer(std::size_t max_length = kMaxLineLength) : max_(max_length) { line_.reserve(max_ + 1); }

  // Feeds bytes; calls on_line(const FramedLine&) for each complete line, in order.
  template <class OnLine>
  void feed(std::string_view bytes, OnLine&& on_line) {
    for (char c : bytes)
      if (take(static_cast<unsigned char>(c))) {
        on_line(FramedLine{line_, overlong_});
        line_.clear();
        overlong_ = false;
      }
  }

  // Bytes held of an unfinished line.
  std::size_t pending() const { return line_.size(); }

 private:
  bool take(unsigned char c);  // true when c completed a line
  bool data(unsigned char c);  // a byte outside any telnet sequence
  void keep(unsigned char c);  // appends to the line, or marks it overlong

  enum class Telnet { Data, Iac, Option, Sub, SubIac };
  std::size_t max_;
  std::string line_;
  bool overlong_ = false;
  Telnet telnet_ = Telnet::Data;
  std::size_t sub_bytes_ = 0;  // bytes seen in the current subnegotiation
  bool cr_ = false;            // a CR was read; the next byte decides whether it ends the line
  bool after_cr_nul_ = false;  // the line just ended with CR NUL: an LF right after belongs to it
};

}  // namespace imess::protocol
