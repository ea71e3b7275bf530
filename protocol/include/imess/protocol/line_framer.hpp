// LineFramer: turns a TCP byte stream into protocol lines. Accepts LF or CRLF, strips telnet
// IAC negotiation, and caps the line length so a client cannot grow a buffer without bound.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace imess::protocol {

// Longest accepted line, terminator excluded (1996: 80). Documented in docs/protocol.md.
inline constexpr std::size_t kMaxLineLength = 200;

struct FramedLine {
  std::string_view text;  // without CR/LF and telnet bytes; valid until the next feed()
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

  enum class Telnet { Data, Iac, Option, Sub, SubIac };
  std::size_t max_;
  std::string line_;
  bool overlong_ = false;
  Telnet telnet_ = Telnet::Data;
};

}  // namespace imess::protocol
