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

// FrameReceiver: a FrameDecoder that resynchronises. After a damaged frame the bytes after its
// sync byte are decoded again: the next frame's sync may lie among them (a false sync byte in
// a damaged frame's CRC, or a damaged length byte, had the decoder take the next frames'
// bytes for its payload). Bounded: at most a frame's bytes wait for a second look. Each
// damaged frame is reported once, not the false sync bytes found among its bytes.
// sink(FrameDecoder::Result::Frame or ::Damaged, const FrameDecoder&) for each; no allocation.
class FrameReceiver {
 public:
  explicit FrameReceiver(std::size_t max_payload = kMaxPayload) noexcept : decoder_(max_payload) {}
  template <class Sink>
  void feed(std::uint8_t byte, Sink&& sink) noexcept {
    if (decode(byte, false, sink)) return;
    std::array<std::uint8_t, 2 * kMaxWireFrame> work{};
    std::array<bool, 2 * kMaxWireFrame> again{};
    std::size_t head = 0, n = 0;
    for (;;) {  // damaged: look again at the bytes after its sync byte, ahead of those not yet decoded
      std::array<std::uint8_t, 2 * kMaxWireFrame> rest{};
      std::array<bool, 2 * kMaxWireFrame> rest_again{};
      std::size_t m = 0;
      for (std::size_t i = 1; i < attempt_len_ && m < rest.size(); ++i, ++m) {
        rest[m] = attempt_[i];
        rest_again[m] = true;
      }
      for (std::size_t i = head; i < n && m < rest.size(); ++i, ++m) {
        rest[m] = work[i];
        rest_again[m] = again[i];
      }
      attempt_len_ = 0;
      work = rest;
      again = rest_again;
      head = 0;
      n = m;
      while (head < n && decode(work[head], again[head], sink)) ++head;
      if (head >= n) return;
      ++head;
    }
  }
  void reset() noexcept {
    decoder_.reset();
    attempt_len_ = 0;
  }

 private:
  // One byte through the decoder; false when it ended a damaged frame (attempt_ holds its bytes).
  template <class Sink>
  bool decode(std::uint8_t byte, bool rescanned, Sink& sink) noexcept {
    if (decoder_.hunting()) {
      attempt_len_ = 0;
      attempt_rescanned_ = rescanned;
    }
    if (attempt_len_ < attempt_.size()) attempt_[attempt_len_++] = byte;
    switch (decoder_.feed(byte)) {
      case FrameDecoder::Result::Pending: return true;
      case FrameDecoder::Result::Damaged:
        if (!attempt_rescanned_) sink(FrameDecoder::Result::Damaged, decoder_);
        return false;
      case FrameDecoder::Result::Frame: break;
    }
    attempt_len_ = 0;
    sink(FrameDecoder::Result::Frame, decoder_);
    return true;
  }

  FrameDecoder decoder_;
  std::array<std::uint8_t, kMaxWireFrame> attempt_{};  // the bytes of the frame being decoded
  std::size_t attempt_len_ = 0;
  bool attempt_rescanned_ = false;  // it began in bytes looked at a second time
};

}  // namespace imess::hal
