// The real-time thread. Statistics are summarised inside the loop once a second (a bounded
// walk over the histogram, no allocation) and published through a triple buffer; the
// measuring interval is counted every cycle into lock-free atomics (IntervalStats).
#include "imess/core/loop_runner.hpp"

#include "imess/core/memory_lock.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <time.h>

#include <cerrno>
#include <cstring>

namespace imess::core {

namespace {
timespec to_timespec(Nanos t) {
  timespec ts;
  ts.tv_sec = static_cast<time_t>(t.count() / 1'000'000'000);
  ts.tv_nsec = static_cast<long>(t.count() % 1'000'000'000);
  return ts;
}
}  // namespace

Nanos MonotonicClock::now() const noexcept {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return Nanos(std::int64_t{ts.tv_sec} * 1'000'000'000 + ts.tv_nsec);
}

LoopRunner::LoopRunner(MotionCore& core, const MonotonicClock& clock, Nanos period)
    : core_(core), clock_(clock), period_(period) {}

LoopRunner::~LoopRunner() { stop(); }

std::string LoopRunner::start(bool want_realtime) {
  std::string report;
  if (want_realtime) {
    report = lock_memory().note;
  } else {
    report = "real-time scheduling not requested";
  }
  running_ = true;
  thread_ = std::thread([this] { run(); });
  if (want_realtime) {
    sched_param sp{};
    sp.sched_priority = kPriority;
    int rc = pthread_setschedparam(thread_.native_handle(), SCHED_FIFO, &sp);
    realtime_ = rc == 0;
    report += realtime_ ? "; motion loop on SCHED_FIFO priority " + std::to_string(kPriority)
                        : std::string("; SCHED_FIFO not permitted (") + std::strerror(rc) +
                              "): the motion loop runs time-shared, expect larger latency (run as root or grant CAP_SYS_NICE)";
  }
  pthread_setname_np(thread_.native_handle(), "messd-motion");
  return report;
}

void LoopRunner::stop() {
  if (!running_.exchange(false)) return;
  if (thread_.joinable()) thread_.join();
}

void LoopRunner::run() noexcept {
  Nanos deadline = clock_.now() + wall_period_;
  Nanos last_summary = deadline;
  std::uint64_t cycles = 0;
  while (running_.load(std::memory_order_relaxed)) {
    timespec ts = to_timespec(deadline);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {}
    Nanos woke = clock_.now();
    const double late_us = std::chrono::duration<double, std::micro>(woke - deadline).count();
    latency_.add(late_us);
    core_.cycle(loop_time_ ? loop_time_->advance(period_) : woke);
    Nanos done = clock_.now();
    cycle_time_.add(std::chrono::duration<double, std::micro>(done - woke).count());
    ++cycles;
    deadline += wall_period_;
    const bool overrun = done > deadline;
    if (overrun) {  // missed the next deadline: count it and do not try to catch up
      ++overruns_;
      deadline = done + wall_period_;
    }
    interval_.record(late_us, overrun);
    if (done - last_summary >= std::chrono::seconds(1)) {
      last_summary = done;
      LoopStats& s = stats_.back();
      s.period_us = std::chrono::duration<double, std::micro>(period_).count();
      s.cycles = cycles;
      s.overruns = overruns_;
      s.latency_p50_us = latency_.percentile(0.5);
      s.latency_p99_us = latency_.percentile(0.99);
      s.latency_p999_us = latency_.percentile(0.999);
      s.latency_max_us = latency_.max();
      s.cycle_p99_us = cycle_time_.percentile(0.99);
      s.cycle_max_us = cycle_time_.max();
      s.realtime = realtime_.load(std::memory_order_relaxed);
      stats_.publish();
    }
  }
}

}  // namespace imess::core
