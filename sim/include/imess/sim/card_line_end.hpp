// CardLineEnd: the card's end of a byte line (docs/servo-card-link.md, "A card on a serial
// device"). Bytes from the host go in one at a time; stream frames reach the emulated card's
// stream, set-up frames ({tag, request}) are answered at once with a set-up frame {tag, reply};
// what the card sends (replies and status frames) comes out as encoded frames for the line.
// No allocation, no clock: the caller decides when a byte has arrived and runs the ticks.
#pragma once
#include <array>
#include <cstdint>
#include <span>

#include "imess/hal/stream_frame.hpp"
#include "imess/sim/emulated_card.hpp"

namespace imess::sim {

class CardLineEnd {
 public:
  explicit CardLineEnd(EmulatedCard& card) : card_(card) {}

  // One byte has arrived from the host. A set-up reply, if it made one, is in reply() until the
  // next byte.
  void feed(std::uint8_t byte) noexcept;
  std::span<const std::uint8_t> reply() const noexcept { return {reply_wire_.data(), reply_len_}; }
  // After a tick of the card: the status frame it made, encoded for the line (empty: none).
  std::span<const std::uint8_t> take_status() noexcept;

  unsigned long setup_requests() const noexcept { return setup_requests_; }
  unsigned long stream_frames() const noexcept { return stream_frames_; }
  unsigned long damaged() const noexcept { return damaged_; }

 private:
  EmulatedCard& card_;
  void take(hal::FrameDecoder::Result r, const hal::FrameDecoder& d) noexcept;

  hal::FrameReceiver receiver_;
  std::array<std::uint8_t, hal::kMaxWireFrame> reply_wire_{}, status_wire_{};
  std::size_t reply_len_ = 0;
  unsigned long setup_requests_ = 0, stream_frames_ = 0, damaged_ = 0;
};

}  // namespace imess::sim
