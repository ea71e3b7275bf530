// LatencyHistogram: a timing distribution in 1 µs buckets (the motion loop's wake-up latency
// and cycle time), and the percentile rule every reader of such buckets shares.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

namespace imess::core {

// The bucket `b` holds the samples from b to b+1 µs; the last bucket everything longer.
inline constexpr std::size_t kLatencyBuckets = 5001;

// The p-quantile (p in [0, 1]) of `count` samples in 1 µs buckets: the bucket holding the
// sample of rank floor(p × (count − 1)), reported as its middle (b + 0.5 µs), never above the
// largest sample `max`. 0 without samples.
double bucket_percentile(const std::uint32_t* buckets, std::size_t n, std::uint64_t count, double max,
                         double p) noexcept;

class LatencyHistogram {
 public:
  static constexpr std::size_t kBuckets = kLatencyBuckets;
  void add(double us) noexcept;
  double percentile(double p) const noexcept;  // p in [0, 1]
  double max() const noexcept { return max_; }
  std::uint64_t count() const noexcept { return count_; }

 private:
  std::array<std::uint32_t, kBuckets> buckets_{};
  std::uint64_t count_ = 0;
  double max_ = 0;
};

// The bucket of a sample of `us` microseconds.
constexpr std::size_t latency_bucket(double us) noexcept {
  std::size_t b = us <= 0 ? 0 : static_cast<std::size_t>(us);
  return b >= kLatencyBuckets ? kLatencyBuckets - 1 : b;
}

}  // namespace imess::core
