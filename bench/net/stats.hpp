// Percentiles from raw samples (nearest rank, no interpolation, no histogram) and the
// thinning of a sample set for the JSON file.
#pragma once
#include <cstddef>
#include <vector>

namespace imess::bench {

// The p-quantile (0 < p <= 1) by nearest rank: the smallest sample with at least p of all
// samples at or below it. 0 for no samples (callers report an empty set as unavailable).
double percentile(std::vector<double> samples, double p);
double median(const std::vector<double>& samples);
double min_of(const std::vector<double>& samples);
double max_of(const std::vector<double>& samples);

// At most `cap` samples, evenly spaced through the set in its order (the order of taking).
std::vector<double> thinned(const std::vector<double>& samples, std::size_t cap = 20000);

// Least-squares slope of y over x (0 with fewer than two distinct x).
double slope(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace imess::bench
