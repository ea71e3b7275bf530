// The base-period thread: clock_nanosleep(TIMER_ABSTIME) to each deadline, never catching
// up a missed period (a burst of late ticks would squeeze step pulses).
#include "base_thread.hpp"

#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <cerrno>
#include <cstring>

namespace imess::app {

namespace {
std::int64_t now_ns() {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return std::int64_t{ts.tv_sec} * 1'000'000'000 + ts.tv_nsec;
}
}  // namespace

std::string BaseThread::start(bool want_realtime) {
  running_ = true;
  thread_ = std::thread([this] { run(); });
  pthread_setname_np(thread_.native_handle(), "messd-base");
  if (!want_realtime) return "base thread time-shared (real time not requested)";
  sched_param sp{};
  sp.sched_priority = kPriority;
  int rc = pthread_setschedparam(thread_.native_handle(), SCHED_FIFO, &sp);
  return rc == 0 ? "base thread on SCHED_FIFO priority " + std::to_string(kPriority)
                 : std::string("base thread: SCHED_FIFO not permitted (") + std::strerror(rc) +
                       "): step timing will jitter; run as root or grant CAP_SYS_NICE";
}

void BaseThread::stop() {
  if (!running_.exchange(false)) return;
  if (thread_.joinable()) thread_.join();
}

void BaseThread::run() noexcept {
  const std::int64_t period = driver_.base_period().count();
  std::int64_t deadline = now_ns() + period;
  while (running_.load(std::memory_order_relaxed)) {
    timespec ts{static_cast<time_t>(deadline / 1'000'000'000), static_cast<long>(deadline % 1'000'000'000)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {}
    const std::int64_t woke = observer_ ? now_ns() : 0;
    driver_.base_tick();
    ticks_.fetch_add(1, std::memory_order_relaxed);
    const std::int64_t done = now_ns();
    const bool overrun = done > deadline + period;
    if (observer_) observer_->tick(woke - deadline, done - deadline, overrun);
    deadline += period;
    if (overrun) {
      overruns_.fetch_add(1, std::memory_order_relaxed);
      deadline = done + period;
    }
  }
}

}  // namespace imess::app
