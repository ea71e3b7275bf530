// The y/N question.
#include "confirm.hpp"

#include <cctype>
#include <string>

namespace imess::messoffs {

bool confirmed(std::istream& in, std::ostream& prompt, std::string_view question) {
  prompt << question << " [y/N] " << std::flush;
  std::string line;
  if (!std::getline(in, line)) return false;
  std::string word;
  for (char c : line)
    if (!std::isspace(static_cast<unsigned char>(c))) word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return word == "y" || word == "yes";
}

}  // namespace imess::messoffs
