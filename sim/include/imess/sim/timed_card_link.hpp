// TimedCardLink: the emulated card behind a full-duplex serial line with real byte timing in
// virtual time (a SerialChannel each way, 115 200 baud by default). The driver's StreamLink:
// frames (hal/stream_frame.hpp) go out byte by byte and reach the card's decoder when their
// bytes have crossed the line; the card's status frames come back the same way. The card
// runs tick by tick in between, so every frame is handled at the card tick its last byte
// arrives. Set-up requests (hal::Link) are answered at once: set-up is not real-time.
#pragma once
#include <array>

#include "imess/hal/link.hpp"
#include "imess/hal/stream_frame.hpp"
#include "imess/hal/stream_link.hpp"
#include "imess/sim/emulated_card.hpp"
#include "imess/sim/serial_channel.hpp"

namespace imess::sim {

struct LineConfig {
  double baud = 115200;
  double bits_per_byte = 10;
};

class TimedCardLink final : public hal::Link, public hal::StreamLink {
 public:
  TimedCardLink(EmulatedCard& card, const hal::Clock& clock, LineConfig config = {});

  int transact(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept override;
  bool send(std::span<const std::uint8_t> frame) noexcept override;
  int poll(std::span<std::uint8_t> frame) noexcept override;

  SerialChannel& to_card() noexcept { return to_card_; }
  SerialChannel& to_host() noexcept { return to_host_; }
  long damaged_at_card() const noexcept { return damaged_at_card_; }
  long damaged_at_host() const noexcept { return damaged_at_host_; }

 private:
  void sync() noexcept;  // runs the line and the card up to the clock's time

  EmulatedCard& card_;
  const hal::Clock& clock_;
  SerialChannel to_card_, to_host_;
  hal::FrameReceiver card_rx_, host_rx_;
  bool started_ = false;
  double t_start_ = 0;
  long ticks_ = 0;
  // Frames arrived at the host and not yet polled (length 0: a damaged one): as many status
  // frames as a tty's 4 KB receive buffer holds (about 0.4 s of them), so a stalled host
  // finds them all, as on a real line.
  static constexpr std::size_t kInbox = 80;
  std::array<std::array<std::uint8_t, hal::kMaxPayload>, kInbox> inbox_{};
  std::array<std::size_t, kInbox> inbox_len_{};
  std::size_t inbox_head_ = 0, inbox_count_ = 0;
  long damaged_at_card_ = 0, damaged_at_host_ = 0;
};

}  // namespace imess::sim
