// The five figures of a wake-up latency distribution — p50, p99, p99.9, max, overruns — for
// the measured thread against cyclictest's at the same period and priority, and the
// distributions behind them.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "histogram.hpp"
#include "report.hpp"

namespace imess::bench {

struct LatencySide {
  std::string id;       // "rt.loop.idle" / "floor.loop.idle"
  std::string subject;  // "messd loop" / "cyclictest -i 1000 -p 80"
  const Histogram* histogram = nullptr;  // null: unavailable
  std::uint64_t overruns = 0;
  std::string unavailable;               // why, when histogram is null
  std::vector<double> raw_samples_us;    // raw samples for the plots; empty: the histogram's
};

// Adds the measured side's figures with the floor as reference (goals on p99 and p99.9 when
// `goals`), then the floor's own figures, then both distributions. `condition`: "idle", ...
void add_latency_figures(Report& report, const LatencySide& measured, const LatencySide& floor,
                         const std::string& condition, bool goals);

}  // namespace imess::bench
