// Asking the operator before corrections go anywhere: corrections are never applied unseen.
#pragma once
#include <istream>
#include <ostream>
#include <string_view>

namespace imess::messoffs {

// Writes `question` and " [y/N] " to `prompt` and reads one line: true only for y or yes (any
// case, blanks ignored); anything else, an empty line or the end of input is no.
bool confirmed(std::istream& in, std::ostream& prompt, std::string_view question);

}  // namespace imess::messoffs
