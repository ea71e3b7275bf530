// LineFramer byte handling: line terminators (LF, CR LF, CR NUL), telnet command sequences
// (RFC 854) stripped but bounded, and the bytes that make a line unacceptable kept in it.
#include "imess/protocol/line_framer.hpp"

namespace imess::protocol {
namespace {
constexpr unsigned char kIac = 255, kSb = 250, kSe = 240, kWill = 251, kDont = 254;
}

void LineFramer::keep(unsigned char c) {
  if (line_.size() < max_)
    line_.push_back(static_cast<char>(c));
  else
    overlong_ = true;
}

bool LineFramer::take(unsigned char c) {
  const bool lf_after_cr_nul = after_cr_nul_ && c == '\n';
  after_cr_nul_ = false;
  if (lf_after_cr_nul) return false;  // "CR NUL LF": one terminator, not a line and a blank line
  if (c == '\n') {
    // An LF ends the line whatever came before it: a telnet sequence it cuts short leaves
    // an IAC in the line (Err 104), and the next line starts clean.
    if (telnet_ != Telnet::Data) keep(kIac);
    telnet_ = Telnet::Data;
    cr_ = false;
    return true;
  }
  switch (telnet_) {
    case Telnet::Iac:
      if (c == kIac) {  // escaped 0xFF data byte: keep it, the parser rejects it as non-ASCII
        telnet_ = Telnet::Data;
        keep(c);
      } else if (c >= kWill && c <= kDont) {
        telnet_ = Telnet::Option;
      } else if (c == kSb) {
        telnet_ = Telnet::Sub;
        sub_bytes_ = 0;
      } else {
        telnet_ = Telnet::Data;  // a two-byte command (NOP, IP, AYT, ...)
      }
      return false;
    case Telnet::Option:  // the option byte of WILL/WONT/DO/DONT
      telnet_ = Telnet::Data;
      return false;
    case Telnet::Sub:
    case Telnet::SubIac:
      if (telnet_ == Telnet::SubIac && c == kSe) {
        telnet_ = Telnet::Data;
        return false;
      }
      telnet_ = c == kIac && telnet_ == Telnet::Sub ? Telnet::SubIac : Telnet::Sub;
      if (++sub_bytes_ > kMaxSubnegotiation) {  // no IAC SE in sight: give up, mark the line
        telnet_ = Telnet::Data;
        keep(kIac);
      }
      return false;
    case Telnet::Data:
      return data(c);
  }
  return false;
}

bool LineFramer::data(unsigned char c) {
  if (cr_) {
    cr_ = false;
    if (c == '\0') {  // telnet's CR NUL: a line end
      after_cr_nul_ = true;
      return true;
    }
    keep('\r');  // a CR inside the line: kept, so the line is answered with Err 104
  }
  if (c == '\r') {
    cr_ = true;
    return false;
  }
  if (c == kIac) {
    telnet_ = Telnet::Iac;
    return false;
  }
  keep(c);  // NUL and other control bytes stay in the line: Err 104
  return false;
}

}  // namespace imess::protocol
