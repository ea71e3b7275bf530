// The one clock of the network benchmarks: CLOCK_MONOTONIC in nanoseconds — the clock messd
// stamps a Hit's trigger time with (core::MonotonicClock), so both sides of a host read the same.
#pragma once
#include <time.h>

#include <cstdint>

namespace imess::bench {

inline std::int64_t mono_ns() {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return std::int64_t{ts.tv_sec} * 1'000'000'000 + ts.tv_nsec;
}

inline double ns_to_ms(std::int64_t ns) { return static_cast<double>(ns) / 1e6; }
inline double ns_to_s(std::int64_t ns) { return static_cast<double>(ns) / 1e9; }

// Sleeps until mono_ns() >= until_ns (absolute, so the wake-up is not late by the call's own time).
inline void sleep_until_ns(std::int64_t until_ns) {
  timespec ts{static_cast<time_t>(until_ns / 1'000'000'000), static_cast<long>(until_ns % 1'000'000'000)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) != 0) {}
}

}  // namespace imess::bench
