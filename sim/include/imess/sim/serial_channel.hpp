// SerialChannel: one direction of a serial line in virtual time. Bytes queued at time t
// leave one after another, each taking bits_per_byte / baud seconds (10 bits: start, 8 data,
// stop), and arrive when their last bit is through. Faults can be injected into the next
// frame queued: lost (its bytes never arrive) or corrupted (one bit flipped on the way).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace imess::sim {

struct LineStats {
  long bytes = 0, frames = 0;  // queued
  long refused = 0;            // frames that did not fit the queue
  long lost = 0, corrupted = 0;
  double max_backlog = 0;      // s, the longest a frame waited for the line to be free
  long overruns = 0;           // frames that waited longer than the patience (a motion period)
};

class SerialChannel {
 public:
  explicit SerialChannel(double baud, double bits_per_byte = 10)
      : byte_time_(baud > 0 ? bits_per_byte / baud : 0) {}

  // A frame that waits longer than this for the line is an overrun (default: 1 ms, a motion
  // period: its sender's cycle put more on the line than the line carries).
  void set_patience(double seconds) noexcept { patience_ = seconds; }

  enum class Fault { None, Lose, Corrupt };
  void inject(Fault f) noexcept { fault_ = f; }

  // Queues a frame's bytes at time now (s); false when the queue has no room for them.
  bool push(std::span<const std::uint8_t> bytes, double now) noexcept {
    if (bytes.size() > ring_.size() - count_) {
      ++stats_.refused;
      return false;
    }
    const Fault f = fault_;
    fault_ = Fault::None;
    const double start = busy_until_ > now ? busy_until_ : now;
    if (start - now > stats_.max_backlog) stats_.max_backlog = start - now;
    if (start - now > patience_) ++stats_.overruns;
    busy_until_ = start + static_cast<double>(bytes.size()) * byte_time_;
    ++stats_.frames;
    stats_.bytes += static_cast<long>(bytes.size());
    if (f == Fault::Lose) {  // the line was busy with it all the same
      ++stats_.lost;
      return true;
    }
    if (f == Fault::Corrupt) ++stats_.corrupted;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      std::uint8_t b = bytes[i];
      if (f == Fault::Corrupt && i == bytes.size() / 2) b ^= 0x08;
      ring_[(head_ + count_++) % ring_.size()] = {b, start + static_cast<double>(i + 1) * byte_time_};
    }
    return true;
  }

  // Hands every byte that has arrived by time t to sink(byte), in order.
  template <class Sink>
  void deliver(double t, Sink&& sink) {
    while (count_ > 0 && ring_[head_].arrival <= t) {
      const std::uint8_t b = ring_[head_].value;
      head_ = (head_ + 1) % ring_.size();
      --count_;
      sink(b);
    }
  }

  double byte_time() const noexcept { return byte_time_; }
  const LineStats& stats() const noexcept { return stats_; }

 private:
  struct Byte {
    std::uint8_t value = 0;
    double arrival = 0;
  };
  double byte_time_;
  std::array<Byte, 4096> ring_{};
  std::size_t head_ = 0, count_ = 0;
  double busy_until_ = 0, patience_ = 0.001;
  Fault fault_ = Fault::None;
  LineStats stats_;
};

}  // namespace imess::sim
