// LineFramer byte handling: telnet command sequences (RFC 854) never reach a line.
#include "imess/protocol/line_framer.hpp"

namespace imess::protocol {
namespace {
constexpr unsigned char kIac = 255, kSb = 250, kSe = 240, kWill = 251, kDont = 254;
}

bool LineFramer::take(unsigned char c) {
  switch (telnet_) {
    case Telnet::Iac:
      if (c == kIac) {  // escaped 0xFF data byte: keep it, the parser rejects it as non-ASCII
        telnet_ = Telnet::Data;
        break;
      }
      telnet_ = (c >= kWill && c <= kDont) ? Telnet::Option : (c == kSb ? Telnet::Sub : Telnet::Data);
      return false;
    case Telnet::Option:  // the option byte of WILL/WONT/DO/DONT
      telnet_ = Telnet::Data;
      return false;
    case Telnet::Sub:
      if (c == kIac) telnet_ = Telnet::SubIac;
      return false;
    case Telnet::SubIac:
      telnet_ = (c == kSe) ? Telnet::Data : Telnet::Sub;
      return false;
    case Telnet::Data:
      if (c == kIac) {
        telnet_ = Telnet::Iac;
        return false;
      }
      if (c == '\n') return true;
      if (c == '\r' || c == '\0') return false;  // CRLF, and telnet's CR NUL
      break;
  }
  if (line_.size() < max_)
    line_.push_back(static_cast<char>(c));
  else
    overlong_ = true;
  return false;
}

}  // namespace imess::protocol
