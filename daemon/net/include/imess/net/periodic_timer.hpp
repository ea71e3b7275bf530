// PeriodicTimer: a steady timer on a fixed schedule — the next deadline is the previous one
// plus the period, not "now" plus the period (that lost the handler's own time each round:
// ReportHz 100 to 200 clients gave 84 lines a second); more than a whole period late, it skips
// ahead instead of bursting. The period may change between ticks (Set ReportHz, Stream).
#pragma once
#include <boost/asio.hpp>

#include <chrono>
#include <functional>

namespace imess::net {

class PeriodicTimer {
 public:
  using Period = std::function<std::chrono::microseconds()>;
  explicit PeriodicTimer(boost::asio::io_context& io) : timer_(io) {}
  // First tick after `first`, then every period() (asked after each tick).
  void start(std::chrono::microseconds first, Period period, std::function<void()> tick) {
    period_ = std::move(period);
    tick_ = std::move(tick);
    running_ = true;
    timer_.expires_after(first);
    rearm();
  }
  void cancel() {
    running_ = false;
    timer_.cancel();
  }

 private:
  void rearm() {
    timer_.async_wait([this](boost::system::error_code ec) {
      if (ec || !running_) return;
      tick_();
      const auto period = period_();
      auto next = timer_.expiry() + period;
      const auto now = boost::asio::steady_timer::clock_type::now();
      if (next + period < now) next = now + period;
      timer_.expires_at(next);
      rearm();
    });
  }

  boost::asio::steady_timer timer_;
  Period period_;
  std::function<void()> tick_;
  bool running_ = false;
};

}  // namespace imess::net
