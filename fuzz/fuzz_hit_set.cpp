// Fuzz target: hit sets as Align names them ("1-3", "4,5", "7,9-12"). Whatever the text, the
// parser returns numbers or says why not; what it returns is in range, unique and at most 1000.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>

#include "imess/protocol/hit_set.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string why;
  const auto hits = imess::protocol::parse_hit_set(text, why);
  if (hits.empty() == why.empty()) std::abort();  // either numbers or a reason
  if (hits.size() > imess::protocol::kMaxHitSet) std::abort();
  std::set<std::uint64_t> seen;
  for (auto n : hits)
    if (n == 0 || !seen.insert(n).second) std::abort();
  return 0;
}
