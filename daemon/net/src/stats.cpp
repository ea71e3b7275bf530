// Stats: the motion loop's timing since the start (summarised by the loop once a second), and
// over a measuring interval a client restarts with `Stats Reset` and reads with `Stats
// Interval` (figures) or `Stats Hist` (every non-empty 1 µs bucket), so that a benchmark gets
// the distribution of exactly the seconds it measured. `Ok Stats Reset` comes once the loop has
// begun the new interval (the reply slot waits; later replies keep their order).
#include <cstdio>
#include <memory>

#include "imess/net/stats_report.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

namespace {
std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}
}  // namespace

std::string StatsReport::stats_line() {
  core::LoopStats st;
  if (runner_) st = runner_->stats();
  return "Period " + fixed(st.period_us, 0) + " Cycles " + std::to_string(st.cycles) + " LatP50 " +
         fixed(st.latency_p50_us, 1) + " LatP99 " + fixed(st.latency_p99_us, 1) + " LatP999 " +
         fixed(st.latency_p999_us, 1) + " LatMax " + fixed(st.latency_max_us, 1) + " CycleP99 " +
         fixed(st.cycle_p99_us, 1) + " CycleMax " + fixed(st.cycle_max_us, 1) + " Overruns " +
         std::to_string(st.overruns) + " Realtime " + (st.realtime ? "yes" : "no") + " LinkErrors " +
         std::to_string(link_errors_ ? link_errors_() : 0);
}

// Ok Stats Reset once the loop has begun the new interval (within a period), so that whatever
// a client asks after the reply is of the new interval; a loop that stands still longer than
// kMaxWaits polls gets the reply anyway (its interval then begins at its next cycle).
void StatsReport::reply_when_restarted(std::weak_ptr<Session> ws, std::uint32_t slot, int waited) {
  constexpr int kMaxWaits = 10000;  // of 200 µs: 2 s
  if (runner_->interval_restarted() || waited >= kMaxWaits) {
    if (auto s = ws.lock()) sessions_.reply(*s, slot, protocol::format_ok("Stats", "Reset"));
    return;
  }
  auto timer = std::make_shared<boost::asio::steady_timer>(io_, std::chrono::microseconds(200));
  timer->async_wait([this, ws = std::move(ws), slot, waited, timer](const boost::system::error_code& ec) {
    if (!ec) reply_when_restarted(ws, slot, waited + 1);
  });
}

void StatsReport::stats(Session& s, std::uint32_t slot, const protocol::Stats& c) {
  using Form = protocol::Stats::Form;
  using protocol::format_ok;
  switch (c.form) {
    case Form::SinceStart: sessions_.reply(s, slot, format_ok("Stats", stats_line())); return;
    case Form::Reset:
      if (!runner_) {
        sessions_.reply(s, slot, format_ok("Stats", "Reset"));
        return;
      }
      runner_->restart_interval();
      reply_when_restarted(s.weak_from_this(), slot, 0);
      return;
    case Form::Interval:
    case Form::Hist: break;
  }
  auto snap = std::make_unique<core::IntervalSnapshot>();  // 20 KB: not on the io thread's stack
  if (runner_) runner_->interval(*snap);
  if (c.form == Form::Interval) {
    const bool rt = runner_ && runner_->realtime();
    sessions_.reply(s, slot,
          format_ok("Stats", "Interval Period " + fixed(runner_ ? runner_->period_us() : 0, 0) + " Cycles " +
                                 std::to_string(snap->cycles) + " LatP50 " + fixed(snap->percentile(0.5), 1) +
                                 " LatP99 " + fixed(snap->percentile(0.99), 1) + " LatP999 " +
                                 fixed(snap->percentile(0.999), 1) + " LatMax " + fixed(snap->latency_max_us, 1) +
                                 " Overruns " + std::to_string(snap->overruns) + " Realtime " + (rt ? "yes" : "no")));
    return;
  }
  std::string lines;
  for (std::size_t b = 0; b < snap->buckets.size(); ++b)
    if (snap->buckets[b] != 0) lines += "Stats Hist " + std::to_string(b) + " " + std::to_string(snap->buckets[b]) + "\n";
  sessions_.reply(s, slot,
        lines + format_ok("Stats", "Hist Cycles " + std::to_string(snap->cycles) + " LatMax " +
                                       fixed(snap->latency_max_us, 1) + " Overruns " + std::to_string(snap->overruns)));
}

}  // namespace imess::net
