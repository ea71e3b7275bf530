// The card's end of the line: decode, dispatch set-up and stream frames, encode what goes back.
#include "imess/sim/card_line_end.hpp"

namespace imess::sim {

using hal::FrameDecoder;

void CardLineEnd::feed(std::uint8_t byte) noexcept {
  reply_len_ = 0;
  receiver_.feed(byte, [this](FrameDecoder::Result r, const FrameDecoder& d) { take(r, d); });
}

void CardLineEnd::take(FrameDecoder::Result r, const FrameDecoder& d) noexcept {
  if (r == FrameDecoder::Result::Damaged) {
    ++damaged_;
    // A damaged set-up frame is retried by the host; a damaged stream frame is asked for again.
    if (!d.setup()) card_.on_damaged_frame();
    return;
  }
  const auto p = d.payload();
  if (!d.setup()) {
    ++stream_frames_;
    card_.on_stream_frame(p);
    return;
  }
  if (p.size() < 2) return;  // a tag and at least an opcode
  ++setup_requests_;
  std::array<std::uint8_t, hal::kMaxPayload> payload{};
  payload[0] = p[0];
  const int n = card_.handle(p.subspan(1), std::span<std::uint8_t>(payload.data() + 1, payload.size() - 1));
  if (n < 1) return;
  reply_len_ = hal::encode_frame(std::span<const std::uint8_t>(payload.data(), static_cast<std::size_t>(n) + 1),
                                 reply_wire_, hal::kSetupSync);
}

std::span<const std::uint8_t> CardLineEnd::take_status() noexcept {
  std::span<const std::uint8_t> out;
  if (!card_.take_stream_frame(out)) return {};
  const std::size_t n = hal::encode_frame(out, status_wire_);
  return {status_wire_.data(), n};
}

}  // namespace imess::sim
