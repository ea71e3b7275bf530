// StreamLink: an asynchronous, framed byte transport to an intelligent card (a serial line
// in full duplex). Neither call waits for the other side: send() queues a frame's bytes,
// poll() hands over a frame that has arrived complete. Framing and the CRC are the
// transport's (hal/stream_frame.hpp); the frames here are payloads.
#pragma once
#include <cstdint>
#include <span>

namespace imess::hal {

class StreamLink {
 public:
  virtual ~StreamLink() = default;
  // Queues one frame for sending. False when the frame does not fit the transmit queue (or
  // is empty or longer than kMaxPayload). Real-time: noexcept, no allocation, never blocks.
  virtual bool send(std::span<const std::uint8_t> frame) noexcept = 0;
  // The oldest frame received complete since the last poll, copied into frame: its length;
  // 0 when none has arrived; -1 when a frame arrived damaged (failed its CRC, bad length)
  // and was dropped. Real-time: noexcept, no allocation, never blocks.
  virtual int poll(std::span<std::uint8_t> frame) noexcept = 0;
};

}  // namespace imess::hal
