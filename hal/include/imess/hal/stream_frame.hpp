// The stream link's framing (docs/servo-card-link.md, "Stream frames"): sync byte 0xA5,
// u8 payload length (1–kMaxPayload), the payload, CRC-16/CCITT-FALSE of length and payload
// (u16, little-endian). Set-up frames (request/reply over the same line, before and beside the
// stream) start with kSetupSync instead, and their CRC covers the sync byte too, so a damaged
// sync byte never turns one kind into the other. FrameDecoder reassembles both kinds from a
// byte stream and resynchronises on the next sync byte after a damaged frame. No allocation.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace imess::hal {

inline constexpr std::uint8_t kFrameSync = 0xA5;
inline constexpr std::uint8_t kSetupSync = 0x5A;
inline constexpr std::size_t kMaxPayload = 250;
inline constexpr std::size_t kFrameOverhead = 4;  // sync, length, CRC
inline constexpr std::size_t kMaxWireFrame = kMaxPayload + kFrameOverhead;

// CRC-16/CCITT-FALSE: polynomial 0x1021, initial value 0xFFFF, no reflection ("123456789" → 0x29B1).
std::uint16_t crc16(std::span<const std::uint8_t> data, std::uint16_t crc = 0xFFFF) noexcept;

// Writes the frame for payload into out (a stream frame, or with kSetupSync a set-up frame);
// returns its length on the wire, 0 when the payload is empty, longer than kMaxPayload, or out
// is too small.
std::size_t encode_frame(std::span<const std::uint8_t> payload, std::span<std::uint8_t> out,
                         std::uint8_t sync = kFrameSync) noexcept;

class FrameDecoder {
 public:
  enum class Result { Pending, Frame, Damaged };
  // max_payload: longer frames are damaged at their length byte (a receiver that knows the
  // longest frame it can get does not wait for the bytes of a damaged length).
  explicit FrameDecoder(std::size_t max_payload = kMaxPayload) noexcept
      : max_(max_payload < 1 ? 1 : max_payload > kMaxPayload ? kMaxPayload : max_payload) {}
  // One byte from the line. Frame: payload() holds a complete frame until the next feed().
  // Damaged: a frame failed its CRC or had length 0; the decoder hunts for the next sync.
  Result feed(std::uint8_t byte) noexcept;
  std::span<const std::uint8_t> payload() const noexcept { return {buf_.data(), len_}; }
  // The frame (or damaged frame) just reported was a set-up frame (kSetupSync).
  bool setup() const noexcept { return sync_ == kSetupSync; }
  void reset() noexcept { state_ = State::Hunt; }
  // Between frames: the next byte is looked at as a possible sync byte.
  bool hunting() const noexcept { return state_ == State::Hunt; }

 private:
  enum class State { Hunt, Length, Payload, CrcLow, CrcHigh };
  State state_ = State::Hunt;
  std::array<std::uint8_t, kMaxPayload> buf_{};
  std::size_t len_ = 0, got_ = 0;
  std::uint16_t crc_ = 0;
  std::uint8_t sync_ = kFrameSync;
  std::size_t max_ = kMaxPayload;
};

}  // namespace imess::hal
