// CountingPort: a PortIo that forwards to another and counts the reads and writes, so that a
// base tick's port accesses on the simulated port can be priced as a real port's (~1 µs each
// on an ISA-compatible parallel port).
#pragma once
#include <atomic>
#include <cstdint>

#include "imess/hal/port_io.hpp"

namespace imess::bench {

class CountingPort final : public hal::PortIo {
 public:
  explicit CountingPort(hal::PortIo& inner) : inner_(inner) {}
  std::uint8_t in8(std::uint16_t port) noexcept override { return count(reads_), inner_.in8(port); }
  void out8(std::uint16_t port, std::uint8_t value) noexcept override { count(writes_), inner_.out8(port, value); }
  std::uint16_t in16(std::uint16_t port) noexcept override { return count(reads_), inner_.in16(port); }
  void out16(std::uint16_t port, std::uint16_t value) noexcept override { count(writes_), inner_.out16(port, value); }
  std::string describe() const override { return inner_.describe() + ", counted"; }
  std::uint64_t reads() const noexcept { return reads_.load(std::memory_order_relaxed); }
  std::uint64_t writes() const noexcept { return writes_.load(std::memory_order_relaxed); }

 private:
  // One writer at a time (set-up, then the base thread alone): no read-modify-write.
  static void count(std::atomic<std::uint64_t>& n) noexcept { n.store(n.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed); }
  hal::PortIo& inner_;
  std::atomic<std::uint64_t> reads_{0}, writes_{0};
};

}  // namespace imess::bench
