// The axis status word and input bits in the card's layout, built from what every backend
// knows about an axis, and the encoder-index window of the port backends (counts since the
// home switch).
#pragma once
#include <cstdint>

#include "imess/hal/motion_backend.hpp"

namespace imess::hal {

struct AxisFlags {
  bool limit_neg = false, limit_pos = false;  // hard limit switches closed
  bool profile_done = false, closed_loop = false, in_position = false, latch_valid = false;
};

constexpr std::uint32_t status_word(const AxisFlags& f, std::uint32_t faults = 0) noexcept {
  std::uint32_t s = faults;
  if (f.limit_neg) s |= status::kHardLimitNeg;
  if (f.limit_pos) s |= status::kHardLimitPos;
  if (f.profile_done) s |= status::kProfileEnd;
  if (f.closed_loop) s |= status::kClosedLoop;
  if (f.in_position) s |= status::kInPosition;
  if (f.latch_valid) s |= status::kLatchValid;
  return s;
}

struct AxisInputs {
  bool limit_neg = false, limit_pos = false, tip = false, home = false, index = false;
};

constexpr std::uint8_t input_bits(const AxisInputs& i) noexcept {
  std::uint8_t bits = 0;
  if (i.limit_pos) bits |= input::kLimitPos;
  if (i.limit_neg) bits |= input::kLimitNeg;
  if (i.tip) bits |= input::kTip;
  if (i.home) bits |= input::kHome;
  if (i.index) bits |= input::kIndex;
  return bits;
}

// The index mark repeats every pitch counts after the home switch released, width counts
// wide, centred half a pitch on (so it is never at the switch edge itself).
constexpr bool in_index_window(std::int64_t counts_since_release, std::int64_t pitch, std::int64_t width) noexcept {
  if (pitch <= 0) return false;
  const std::int64_t phase = ((counts_since_release % pitch) + pitch) % pitch;
  return phase >= pitch / 2 && phase < pitch / 2 + width;
}

}  // namespace imess::hal
