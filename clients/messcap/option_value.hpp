// Reading one option with a value in any of its spellings: "-n 3", "-n3", "--count 3",
// "--count=3" (long-only options pass an empty short name).
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "imess/client/usage_error.hpp"

namespace imess::messcap {

// Matches argv[i]; advances i past a separate value. Throws UsageError when the value is missing.
inline std::optional<std::string_view> option_value(std::string_view shortname, std::string_view longname, int& i,
                                                    int argc, const char* const argv[]) {
  std::string_view a = argv[i];
  std::optional<std::string_view> attached;
  if (a == shortname || a == longname) {
    if (i + 1 >= argc) throw client::UsageError(std::string(a) + " needs a value (see messcap --help)");
    return std::string_view(argv[++i]);
  }
  if (!shortname.empty() && a.size() > shortname.size() && a.substr(0, shortname.size()) == shortname)
    return a.substr(shortname.size());
  if (a.size() > longname.size() && a.substr(0, longname.size()) == longname && a[longname.size()] == '=')
    return a.substr(longname.size() + 1);
  return std::nullopt;
}

}  // namespace imess::messcap
