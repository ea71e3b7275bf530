// Link: the byte transport to an intelligent card — one request frame, one reply frame.
// A serial line, a PC plug-in card's registers, or the emulated card in sim/.
#pragma once
#include <cstdint>
#include <span>

namespace imess::hal {

class Link {
 public:
  virtual ~Link() = default;
  // Sends request and receives the reply into reply. Returns the reply length, or -1 on a
  // transport error or timeout. Real-time: noexcept, no allocation.
  virtual int transact(std::span<const std::uint8_t> request, std::span<std::uint8_t> reply) noexcept = 0;
};

}  // namespace imess::hal
