// TripleBuffer: one writer publishes a whole value, one reader takes the newest whole value;
// neither ever waits for the other (no locks, no torn reads, no allocation).
#pragma once
#include <array>
#include <atomic>
#include <cstdint>

namespace imess::core {

template <class T>
class TripleBuffer {
 public:
  // Writer: fill back(), then publish().
  T& back() noexcept { return slots_[back_]; }
  void publish() noexcept {
    std::uint8_t prev = middle_.exchange(static_cast<std::uint8_t>(back_ | kFresh), std::memory_order_acq_rel);
    back_ = prev & kIndex;
  }
  // Reader: the newest published value (the previous one again if nothing new came).
  const T& read() noexcept {
    if (middle_.load(std::memory_order_acquire) & kFresh) {
      std::uint8_t prev = middle_.exchange(front_, std::memory_order_acq_rel);
      front_ = prev & kIndex;
    }
    return slots_[front_];
  }

 private:
  static constexpr std::uint8_t kIndex = 0x3, kFresh = 0x4;
  std::array<T, 3> slots_{};
  std::uint8_t back_ = 0, front_ = 1;
  std::atomic<std::uint8_t> middle_{2};
};

}  // namespace imess::core
