// The motion loop's measuring interval: counts, restart at the writer's next record, the
// shared percentile rule, and copies taken while the writer runs.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include "imess/core/interval_stats.hpp"

using imess::core::IntervalSnapshot;
using imess::core::IntervalStats;
using imess::core::LatencyHistogram;

TEST_CASE("the interval counts wake-up latencies in 1 us buckets, overruns and the largest") {
  IntervalStats stats;
  auto snap = std::make_unique<IntervalSnapshot>();
  stats.snapshot(*snap);
  CHECK(snap->cycles == 0);
  CHECK(snap->percentile(0.99) == 0);
  for (double us : {2.2, 2.9, 3.1, 7.0, 9000.0}) stats.record(us, false);
  stats.record(1.0, true);
  stats.snapshot(*snap);
  CHECK(snap->cycles == 6);
  CHECK(snap->buckets[2] == 2);
  CHECK(snap->buckets[3] == 1);
  CHECK(snap->buckets[imess::core::kLatencyBuckets - 1] == 1);  // 9 ms: the last bucket holds everything longer
  CHECK(snap->overruns == 1);
  CHECK(snap->latency_max_us == 9000.0);
}

TEST_CASE("percentiles of the interval follow the rule of the since-start histogram") {
  IntervalStats stats;
  LatencyHistogram since_start;
  for (int i = 0; i < 10000; ++i) {
    const double us = (i * 37 % 1000) / 10.0 + (i % 997 == 0 ? 400 : 0);
    stats.record(us, false);
    since_start.add(us);
  }
  auto snap = std::make_unique<IntervalSnapshot>();
  stats.snapshot(*snap);
  for (double p : {0.0, 0.5, 0.99, 0.999, 1.0}) {
    INFO(p);
    CHECK(snap->percentile(p) == since_start.percentile(p));
  }
  CHECK(snap->latency_max_us == since_start.max());
}

TEST_CASE("a restart takes effect at the writer's next record, not before") {
  IntervalStats stats;
  for (int i = 0; i < 100; ++i) stats.record(5, i == 3);
  stats.request_restart();
  CHECK_FALSE(stats.restarted());
  auto snap = std::make_unique<IntervalSnapshot>();
  stats.snapshot(*snap);
  CHECK(snap->cycles == 100);  // the loop has not seen it yet
  stats.record(1.5, false);
  CHECK(stats.restarted());
  stats.snapshot(*snap);
  CHECK(snap->cycles == 1);
  CHECK(snap->buckets[1] == 1);
  CHECK(snap->buckets[5] == 0);
  CHECK(snap->overruns == 0);
  CHECK(snap->latency_max_us == 1.5);
}

TEST_CASE("copies taken while the writer records and restarts are whole: counts sum to cycles, no torn restart") {
  IntervalStats stats;
  std::atomic<bool> done{false};
  // The writer records cycles in pairs 1 us and 2 us, restarting now and then: a whole copy
  // has equal counts in buckets 1 and 2 or one more in bucket 1. Like the loop it rests
  // between bursts (the loop records once a period); a reader that never found a rest (a
  // host so busy that every retry met a write) says so, and that copy is not judged.
  std::thread writer([&] {
    for (int i = 0; i < 400000; ++i) {
      stats.record(1.5, false);
      stats.record(2.5, false);
      if (i % 5000 == 0) stats.request_restart();
      if (i % 64 == 0) std::this_thread::sleep_for(std::chrono::microseconds(20));
    }
    done = true;
  });
  auto snap = std::make_unique<IntervalSnapshot>();
  long copies = 0, whole = 0, last_resort = 0;
  while (!done) {
    if (!stats.snapshot(*snap)) {
      ++last_resort;
      continue;
    }
    ++copies;
    const auto ones = snap->buckets[1], twos = snap->buckets[2];
    if (snap->cycles == std::uint64_t{ones} + twos && (ones == twos || ones == twos + 1 || ones + 1 == twos)) ++whole;
  }
  writer.join();
  INFO(copies << " copies of one moment, " << last_resort << " last-resort copies");
  CHECK(copies > 0);
  CHECK(whole == copies);
}
