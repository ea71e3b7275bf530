// Hit sets: "1-3", "4,5", "7,9-12".
#include "imess/protocol/hit_set.hpp"

#include <algorithm>
#include <charconv>

namespace imess::protocol {
namespace {

constexpr const char* kAccepted = "accepted: hit numbers and ranges separated by commas, such as 1-3 or 4,5 or 7,9-12";

bool read_number(std::string_view t, std::uint64_t& out) {
  if (t.empty() || t.size() > 19) return false;
  for (char c : t)
    if (c < '0' || c > '9') return false;
  std::from_chars(t.data(), t.data() + t.size(), out);
  return out > 0;
}

}  // namespace

std::vector<std::uint64_t> parse_hit_set(std::string_view text, std::string& why) {
  std::vector<std::uint64_t> out;
  auto refuse = [&](std::string_view part, std::string_view what) {
    why = "hits '" + std::string(text.substr(0, 40)) + "': " + std::string(what) + " '" + std::string(part.substr(0, 40)) + "'; " + kAccepted;
    return std::vector<std::uint64_t>{};
  };
  if (text.empty()) return refuse(text, "nothing in");
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view part = text.substr(start, comma - start);
    const std::size_t dash = part.find('-');
    std::uint64_t from = 0, to = 0;
    if (dash == std::string_view::npos) {
      if (!read_number(part, from)) return refuse(part, "not a hit number (1 or more)");
      to = from;
    } else if (!read_number(part.substr(0, dash), from) || !read_number(part.substr(dash + 1), to)) {
      return refuse(part, "not a range of hit numbers");
    } else if (to < from) {
      return refuse(part, "a range running backwards");
    }
    if (to - from >= kMaxHitSet || out.size() + (to - from + 1) > kMaxHitSet)
      return refuse(part, "more than 1000 hits at");
    for (std::uint64_t n = from; n <= to; ++n) {
      if (std::find(out.begin(), out.end(), n) != out.end()) return refuse(part, "a hit named twice in");
      out.push_back(n);
    }
    start = comma + 1;
  }
  why.clear();
  return out;
}

}  // namespace imess::protocol
