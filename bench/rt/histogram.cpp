// 1 µs latency buckets, read with messd's own percentile rule.
#include "histogram.hpp"

#include <algorithm>

#include "imess/core/latency_histogram.hpp"

namespace imess::bench {

Histogram::Histogram() : buckets_(core::kLatencyBuckets, 0) {}

void Histogram::add(double us, std::uint32_t n) {
  buckets_[core::latency_bucket(us)] += n;
  count_ += n;
  max_us_ = std::max(max_us_, us);
}

double Histogram::percentile(double p) const {
  return core::bucket_percentile(buckets_.data(), buckets_.size(), count_, max_us_, p);
}

std::uint64_t Histogram::at_least(double us) const {
  std::uint64_t n = 0;
  for (std::size_t b = core::latency_bucket(us); b < buckets_.size(); ++b) n += buckets_[b];
  return n;
}

std::vector<double> Histogram::plot_samples(std::size_t limit) const {
  std::vector<double> out;
  if (count_ == 0 || limit == 0) return out;
  const std::uint64_t k = std::min<std::uint64_t>(count_, limit);
  out.reserve(k);
  std::size_t b = 0;
  std::uint64_t seen = buckets_[0];
  for (std::uint64_t i = 0; i < k; ++i) {
    const auto rank = k == 1 ? 0 : static_cast<std::uint64_t>(static_cast<double>(i) * static_cast<double>(count_ - 1) /
                                                                static_cast<double>(k - 1));
    while (seen <= rank && b + 1 < buckets_.size()) seen += buckets_[++b];
    out.push_back(std::min(static_cast<double>(b) + 0.5, max_us_));
  }
  return out;
}

}  // namespace imess::bench
