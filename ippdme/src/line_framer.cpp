// LineFramer byte handling: CR LF ends a line; anything else outside 32..126 marks it illegal.
#include "imess/ippdme/line_framer.hpp"

namespace imess::ippdme {

void LineFramer::mark(LineFault f) {
  if (fault_ == LineFault::None) fault_ = f;  // the first fault found is the one reported
}

void LineFramer::keep(unsigned char c) {
  if (line_.size() < max_)
    line_.push_back(static_cast<char>(c));
  else
    mark(LineFault::TooLong);
}

bool LineFramer::take(unsigned char c) {
  const bool after_cr = cr_;
  cr_ = false;
  if (c == '\n') {
    if (!after_cr) mark(LineFault::IllegalCharacter);  // LF without its CR
    return true;
  }
  if (after_cr) {  // a CR in mid-line
    mark(LineFault::IllegalCharacter);
    keep('\r');
  }
  if (c == '\r') {
    cr_ = true;
    return false;
  }
  if (c < 32 || c > 126) mark(LineFault::IllegalCharacter);
  keep(c);
  return false;
}

}  // namespace imess::ippdme
