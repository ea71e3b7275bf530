// Setting values in a 1996 messdrc ("Key value  # comment" lines) without disturbing the rest:
// how `messcap qualify --rc` stores a qualification for messd's next start.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace imess::messcap {

class MessdrcEditError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RcSetting {
  std::string key;      // e.g. "TipRadius"
  std::string value;    // as it is to be written, e.g. "1.999998"
  std::string comment;  // written after the value only when the key is appended
};

// `text` with each setting's line holding its new value (the comment on that line and its
// column kept where the value allows), settings the text lacks appended at the end, every other
// line unchanged. A key given on two lines is an error (messd refuses such a file), named with
// `source` and both line numbers.
std::string set_messdrc_values(std::string_view text, const std::vector<RcSetting>& settings, const std::string& source);

}  // namespace imess::messcap
