// The card's end of the line: decode, dispatch set-up and stream frames, encode what goes back.
#include "imess/sim/card_line_end.hpp"

namespace imess::sim {

using hal::FrameDecoder;

void CardLineEnd::feed(std::uint8_t byte) noexcept {
  reply_len_ = 0;
  switch (decoder_.feed(byte)) {
    case FrameDecoder::Result::Pending: return;
    case FrameDecoder::Result::Damaged:
      ++damaged_;
      // A damaged set-up frame is retried by the host; a damaged stream frame breaks the stream.
      if (!decoder_.setup()) card_.on_damaged_frame();
      return;
    case FrameDecoder::Result::Frame: break;
  }
  const auto p = decoder_.payload();
  if (!decoder_.setup()) {
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
