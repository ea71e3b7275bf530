// Percentiles by nearest rank, thinning and a least-squares slope.
#include "stats.hpp"

#include <algorithm>
#include <cmath>

namespace imess::bench {

double percentile(std::vector<double> samples, double p) {
  if (samples.empty()) return 0;
  std::sort(samples.begin(), samples.end());
  const double rank = std::ceil(p * static_cast<double>(samples.size()));
  const auto i = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(samples.size()))) - 1;
  return samples[i];
}

double median(const std::vector<double>& samples) { return percentile(samples, 0.5); }

double min_of(const std::vector<double>& samples) {
  return samples.empty() ? 0 : *std::min_element(samples.begin(), samples.end());
}

double max_of(const std::vector<double>& samples) {
  return samples.empty() ? 0 : *std::max_element(samples.begin(), samples.end());
}

std::vector<double> thinned(const std::vector<double>& samples, std::size_t cap) {
  if (samples.size() <= cap) return samples;
  std::vector<double> out;
  out.reserve(cap);
  const double step = static_cast<double>(samples.size()) / static_cast<double>(cap);
  for (std::size_t i = 0; i < cap; ++i) out.push_back(samples[static_cast<std::size_t>(static_cast<double>(i) * step)]);
  return out;
}

double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = std::min(x.size(), y.size());
  if (n < 2) return 0;
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxx > 0 ? sxy / sxx : 0;
}

}  // namespace imess::bench
