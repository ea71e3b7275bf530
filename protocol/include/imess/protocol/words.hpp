// Word comparison on the wire: verbs and parameter names are case-insensitive ASCII.
#pragma once
#include <cctype>
#include <string_view>

namespace imess::protocol {

inline bool iequals(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

}  // namespace imess::protocol
