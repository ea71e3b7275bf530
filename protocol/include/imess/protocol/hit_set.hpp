// A set of journaled hits named on the wire (Align): sequence numbers and ranges separated by
// commas, "1-3", "4,5", "7,9-12". Pure; shared by the daemon and clients that build the text.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace imess::protocol {

inline constexpr std::size_t kMaxHitSet = 1000;  // hits in one set

// The numbers in the order written (a range ascending), or empty with `why` saying what was
// wrong and what is accepted. Refused: 0, a range running backwards, more than kMaxHitSet
// numbers, a number named twice, anything but digits, '-' and ','.
std::vector<std::uint64_t> parse_hit_set(std::string_view text, std::string& why);

}  // namespace imess::protocol
