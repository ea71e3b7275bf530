// SpscRing: a fixed-size lock-free ring between exactly one producer thread and one consumer
// thread (the motion thread on one side, a link's I/O thread on the other). No allocation, no
// lock; push and pop never wait. T must be trivially copyable.
#pragma once
#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <span>
#include <type_traits>

namespace imess::hal {

template <class T, std::size_t N>
class SpscRing {
  static_assert(std::is_trivially_copyable_v<T>);
  static_assert(N >= 2 && (N & (N - 1)) == 0, "a power of two");

 public:
  // Producer: false when full (nothing is written).
  bool push(const T& v) noexcept {
    const std::size_t t = tail_.load(std::memory_order_relaxed);
    if (t - head_.load(std::memory_order_acquire) == N) return false;
    buf_[t % N] = v;
    tail_.store(t + 1, std::memory_order_release);
    return true;
  }
  // Producer: all of items or none (false when they do not fit).
  bool push_all(std::span<const T> items) noexcept {
    const std::size_t t = tail_.load(std::memory_order_relaxed);
    if (N - (t - head_.load(std::memory_order_acquire)) < items.size()) return false;
    for (std::size_t i = 0; i < items.size(); ++i) buf_[(t + i) % N] = items[i];
    tail_.store(t + items.size(), std::memory_order_release);
    return true;
  }
  // Consumer: false when empty.
  bool pop(T& v) noexcept {
    const std::size_t h = head_.load(std::memory_order_relaxed);
    if (h == tail_.load(std::memory_order_acquire)) return false;
    v = buf_[h % N];
    head_.store(h + 1, std::memory_order_release);
    return true;
  }
  // Consumer: up to out.size() items; how many.
  std::size_t pop_some(std::span<T> out) noexcept {
    const std::size_t h = head_.load(std::memory_order_relaxed);
    const std::size_t n = std::min(out.size(), tail_.load(std::memory_order_acquire) - h);
    for (std::size_t i = 0; i < n; ++i) out[i] = buf_[(h + i) % N];
    head_.store(h + n, std::memory_order_release);
    return n;
  }

 private:
  std::array<T, N> buf_{};
  alignas(64) std::atomic<std::size_t> head_{0};  // the consumer's
  alignas(64) std::atomic<std::size_t> tail_{0};  // the producer's
};

}  // namespace imess::hal
