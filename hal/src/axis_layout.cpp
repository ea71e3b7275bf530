// Axis layouts from letters (set-up code: throws with a message naming the problem).
#include <algorithm>
#include <stdexcept>

#include "imess/hal/types.hpp"

namespace imess::hal {

AxisLayout make_layout(const std::string& letters) {
  const std::string accepted = "1 to 9 axis letters from X Y Z A B C U V W, each once, e.g. \"XYZ\" or \"XYCUV\"";
  if (letters.empty() || letters.size() > static_cast<std::size_t>(kMaxAxes))
    throw std::invalid_argument("\"" + letters + "\" has " + std::to_string(letters.size()) + " letters; " + accepted);
  AxisLayout l;
  l.count = static_cast<int>(letters.size());
  l.letters.fill('\0');
  for (int a = 0; a < l.count; ++a) {
    const char c = letters[static_cast<std::size_t>(a)];
    if (std::find(kAxisLetters.begin(), kAxisLetters.end(), c) == kAxisLetters.end())
      throw std::invalid_argument(std::string("'") + c + "' is not an axis letter; " + accepted);
    if (l.index_of(c) >= 0) throw std::invalid_argument(std::string("axis ") + c + " is named twice; " + accepted);
    l.letters[a] = c;
    l.kinds[a] = default_kind(c);
  }
  return l;
}

}  // namespace imess::hal
