// Stream framing: CRC-16/CCITT-FALSE, the frame writer and the byte-by-byte decoder.
#include "imess/hal/stream_frame.hpp"

namespace imess::hal {

std::uint16_t crc16(std::span<const std::uint8_t> data, std::uint16_t crc) noexcept {
  for (std::uint8_t b : data) {
    crc ^= static_cast<std::uint16_t>(b << 8);
    for (int i = 0; i < 8; ++i)
      crc = static_cast<std::uint16_t>((crc & 0x8000) ? (crc << 1) ^ 0x1021 : crc << 1);
  }
  return crc;
}

std::size_t encode_frame(std::span<const std::uint8_t> payload, std::span<std::uint8_t> out,
                         std::uint8_t sync) noexcept {
  const std::size_t n = payload.size();
  if (n == 0 || n > kMaxPayload || out.size() < n + kFrameOverhead) return 0;
  out[0] = sync;
  out[1] = static_cast<std::uint8_t>(n);
  for (std::size_t i = 0; i < n; ++i) out[2 + i] = payload[i];
  // A set-up frame's CRC covers its sync byte too.
  const std::uint16_t crc = sync == kFrameSync ? crc16(out.subspan(1, n + 1)) : crc16(out.subspan(0, n + 2));
  out[n + 2] = static_cast<std::uint8_t>(crc);
  out[n + 3] = static_cast<std::uint8_t>(crc >> 8);
  return n + kFrameOverhead;
}

FrameDecoder::Result FrameDecoder::feed(std::uint8_t byte) noexcept {
  switch (state_) {
    case State::Hunt:
      if (byte == kFrameSync || byte == kSetupSync) {
        sync_ = byte;
        state_ = State::Length;
      }
      return Result::Pending;
    case State::Length:
      if (byte == 0 || byte > max_) {
        state_ = State::Hunt;
        return Result::Damaged;
      }
      len_ = byte;
      got_ = 0;
      crc_ = sync_ == kFrameSync ? 0xFFFF : crc16(std::span<const std::uint8_t>(&sync_, 1));
      crc_ = crc16(std::span<const std::uint8_t>(&byte, 1), crc_);
      state_ = State::Payload;
      return Result::Pending;
    case State::Payload:
      buf_[got_++] = byte;
      if (got_ == len_) {
        crc_ = crc16(std::span<const std::uint8_t>(buf_.data(), len_), crc_);
        state_ = State::CrcLow;
      }
      return Result::Pending;
    case State::CrcLow:
      if (byte != static_cast<std::uint8_t>(crc_)) {
        state_ = State::Hunt;
        return Result::Damaged;
      }
      state_ = State::CrcHigh;
      return Result::Pending;
    case State::CrcHigh:
      state_ = State::Hunt;
      return byte == static_cast<std::uint8_t>(crc_ >> 8) ? Result::Frame : Result::Damaged;
  }
  return Result::Pending;
}

}  // namespace imess::hal
