// bench_rt's histogram: messd's percentile rule, and samples for plots at evenly spaced ranks.
#include <catch2/catch.hpp>

#include <algorithm>

#include "histogram.hpp"
#include "imess/core/latency_histogram.hpp"

using imess::bench::Histogram;

TEST_CASE("percentiles are read with the rule of messd's own histogram") {
  Histogram h;
  imess::core::LatencyHistogram messd;
  std::uint64_t from_29 = 0;
  for (int i = 0; i < 5000; ++i) {
    const double us = (i * 7919 % 300) / 10.0;
    h.add(us);
    messd.add(us);
    from_29 += us >= 29 ? 1 : 0;
  }
  for (double p : {0.0, 0.5, 0.99, 0.999, 1.0}) CHECK(h.percentile(p) == messd.percentile(p));
  CHECK(h.count() == 5000);
  CHECK(h.at_least(29) == from_29);
}

TEST_CASE("plot samples keep the distribution: all of few samples, evenly spaced ranks of many") {
  Histogram h;
  h.add(3.2, 9);
  h.add(40, 1);
  auto few = h.plot_samples(100);
  REQUIRE(few.size() == 10);
  CHECK(few.front() == 3.5);
  CHECK(few.back() == 40);  // the bucket's middle would be 40.5, above the largest sample
  Histogram many;
  many.add(1.0, 90000);
  many.add(7.0, 10000);
  auto s = many.plot_samples(1000);
  REQUIRE(s.size() == 1000);
  const auto sevens = std::count(s.begin(), s.end(), 7.0);
  CHECK(sevens >= 99);
  CHECK(sevens <= 101);
  CHECK(Histogram().plot_samples().empty());
}
