// Histogram: a wake-up latency distribution in 1 µs buckets — messd's `Stats Hist`, cyclictest's
// `-h`, or the bench's own raw samples binned — read with the one percentile rule messd uses
// (imess::core::bucket_percentile), so that every figure and its reference are read alike.
#pragma once
#include <cstdint>
#include <vector>

namespace imess::bench {

class Histogram {
 public:
  Histogram();
  void add(double us, std::uint32_t n = 1);  // n samples of `us` µs (past the last bucket: into it)
  void set_max(double us) { max_us_ = us; }   // the largest sample, when known more finely than its bucket
  std::uint64_t count() const { return count_; }
  double max() const { return max_us_; }
  double percentile(double p) const;                // p in [0, 1]; 0 without samples
  std::uint64_t at_least(double us) const;          // samples in the buckets from `us` up
  // At most `limit` samples for plots: the values at evenly spaced ranks (bucket middles, as
  // the percentiles), so their histogram and CDF are those of all samples.
  std::vector<double> plot_samples(std::size_t limit = 20000) const;

 private:
  std::vector<std::uint32_t> buckets_;
  std::uint64_t count_ = 0;
  double max_us_ = 0;
};

}  // namespace imess::bench
