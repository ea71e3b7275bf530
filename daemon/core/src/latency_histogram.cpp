// The 1 µs latency buckets and their percentile rule.
#include "imess/core/latency_histogram.hpp"

namespace imess::core {

double bucket_percentile(const std::uint32_t* buckets, std::size_t n, std::uint64_t count, double max,
                         double p) noexcept {
  if (count == 0) return 0;
  auto rank = static_cast<std::uint64_t>(p * static_cast<double>(count - 1));
  std::uint64_t seen = 0;
  for (std::size_t b = 0; b < n; ++b) {
    seen += buckets[b];
    if (seen > rank) return static_cast<double>(b) + 0.5 < max ? static_cast<double>(b) + 0.5 : max;
  }
  return max;
}

void LatencyHistogram::add(double us) noexcept {
  ++buckets_[latency_bucket(us)];
  ++count_;
  if (us > max_) max_ = us;
}

double LatencyHistogram::percentile(double p) const noexcept {
  return bucket_percentile(buckets_.data(), kBuckets, count_, max_, p);
}

}  // namespace imess::core
