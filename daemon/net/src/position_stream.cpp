// The position stream: CurrCor (and AxPos on a machine whose axes are not exactly X Y Z) to
// every client whenever its printed position changed since that client last got it — at the
// shared ReportHz, or at the client's own Stream rate up to the motion loop's — and the first
// change after rest at once. Each line is formatted once per tick and shared by every queue.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "imess/core/rest_watch.hpp"
#include "imess/net/position_stream.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"

namespace imess::net {
namespace {

using Clock = std::chrono::steady_clock;

Clock::duration period_of(double hz) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / hz));
}

// The next deadline on a fixed schedule; more than a whole period late, it skips ahead.
Clock::time_point next_due(Clock::time_point due, Clock::duration period, Clock::time_point now) {
  due += period;
  return due + period < now ? now + period : due;
}

std::string hz_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

PositionStream::PositionLines PositionStream::position_lines() const {
  const hal::Vec3 p = gateway_.layout().cartesian(gateway_.snapshot().position);
  PositionLines lines;
  lines.curr_cor = std::make_shared<const std::string>(protocol::format_curr_cor({p.x(), p.y(), p.z()}));
  if (!gateway_.layout().is_xyz()) lines.ax_pos = std::make_shared<const std::string>(ax_pos_line());
  return lines;
}

bool PositionStream::send_position(Session& s, const PositionLines& lines) {
  auto& info = s.info();
  bool sent = false;
  if (info.sent_curr_cor != *lines.curr_cor) {
    info.sent_curr_cor = *lines.curr_cor;
    s.send(lines.curr_cor);
    sent = true;
  }
  if (lines.ax_pos && info.sent_ax_pos != *lines.ax_pos) {
    info.sent_ax_pos = *lines.ax_pos;
    s.send(lines.ax_pos);
    sent = true;
  }
  return sent;
}

void PositionStream::report_position() {
  const auto now = Clock::now();
  const bool shared_due = now >= shared_report_due_;
  if (shared_due) {
    shared_report_due_ = next_due(shared_report_due_, period_of(config_.report_hz), now);
    on_shared_tick_();  // a program's Block, I++ DME move reports
  }
  const PositionLines lines = position_lines();
  if (config_.log_traffic && *lines.curr_cor != last_curr_cor_) spdlog::info("[stream] < {}", *lines.curr_cor);
  auto sessions = sessions_.all();  // a send may drop a slow client and erase it
  for (auto& [id, s] : sessions) {
    auto& info = s->info();
    if (info.stream_hz > 0) {
      if (now < info.stream_due) continue;
      info.stream_due = next_due(info.stream_due, period_of(info.stream_hz), now);
    } else if (!shared_due) {
      continue;
    }
    send_position(*s, lines);
  }
  if (shared_due) {  // at rest: no change over a whole shared report period
    at_rest_ = *lines.curr_cor == last_curr_cor_ && (!lines.ax_pos || *lines.ax_pos == last_ax_pos_);
    last_curr_cor_ = *lines.curr_cor;
    if (lines.ax_pos) last_ax_pos_ = *lines.ax_pos;
  }
}

// At rest the stream is silent; the first change after it goes out at once, not at the next
// report tick: a jog shows at once whatever the rate. The motion loop wakes us when the
// position leaves a rest (RestWatch, a tenth of the printed digit) and on each of the next
// cycles (RestWatch::kDepartureWakes); each time the position is looked at until its printed
// form changes (a creep that reaches no digit within them is left to the stream). From there
// on each client's stream keeps its rate.
void PositionStream::watch_start_of_motion() {
  if (!config_.stream_position || !at_rest_) return;
  start_watch_until_ = Clock::now() + std::chrono::microseconds(
                                          static_cast<long>(config_.period_us * core::RestWatch::kDepartureWakes));
  report_start_of_motion();
}

void PositionStream::report_start_of_motion() {
  if (!config_.stream_position || !at_rest_) {
    start_watch_until_.reset();
    return;
  }
  const PositionLines lines = position_lines();
  if (*lines.curr_cor == last_curr_cor_ && (!lines.ax_pos || *lines.ax_pos == last_ax_pos_)) {
    if (start_watch_until_ && Clock::now() >= *start_watch_until_) start_watch_until_.reset();
    return;
  }
  start_watch_until_.reset();
  at_rest_ = false;
  last_curr_cor_ = *lines.curr_cor;
  if (lines.ax_pos) last_ax_pos_ = *lines.ax_pos;
  if (config_.log_traffic) spdlog::info("[all] < {}", *lines.curr_cor);
  auto sessions = sessions_.all();
  for (auto& [id, s] : sessions) send_position(*s, lines);
}

// The report timer runs at the fastest rate any client needs.
double PositionStream::report_timer_hz() const {
  double hz = config_.report_hz;
  for (const auto& [id, s] : sessions_.all()) hz = std::max(hz, s->info().stream_hz);
  return hz;
}

std::string PositionStream::set_stream_rate(Session& s, double hz) {
  const double loop_hz = 1e6 / config_.period_us;
  if (hz > loop_hz * (1 + 1e-9))
    return protocol::format_err(protocol::ErrorCode::BadValue,
                                "Stream " + hz_text(hz) + " Hz is faster than the motion loop (" + hz_text(loop_hz) +
                                    " Hz, Period " + hz_text(config_.period_us) + " us): it takes 0.1 up to " +
                                    hz_text(loop_hz) + ", or 0 for ReportHz");
  s.info().stream_hz = hz;
  s.info().stream_due = Clock::now();
  if (hz > 0 && config_.stream_position) {  // a faster rate takes effect now, not at the next slow tick
    report_timer_.cancel();
    schedule(std::chrono::microseconds(0));
  }
  return protocol::format_ok("Stream", hz_text(hz > 0 ? hz : config_.report_hz));
}

PositionStream::PositionStream(boost::asio::io_context& io, ServerConfig& config, MotionGateway& gateway, SessionHub& sessions,
                               std::function<void()> on_shared_tick)
    : io_(io),
      config_(config),
      gateway_(gateway),
      sessions_(sessions),
      on_shared_tick_(std::move(on_shared_tick)),
      report_timer_(io) {}

void PositionStream::start() {
  running_ = true;
  const auto& snap = gateway_.snapshot();  // clients get the position on connect; report changes only
  const hal::Vec3 p = gateway_.layout().cartesian(snap.position);
  last_curr_cor_ = protocol::format_curr_cor({p.x(), p.y(), p.z()});
  if (!gateway_.layout().is_xyz()) last_ax_pos_ = ax_pos_line();
  if (config_.stream_position) schedule(std::chrono::microseconds(static_cast<long>(1e6 / config_.report_hz)));
}

void PositionStream::stop() {
  running_ = false;
  report_timer_.cancel();
}

void PositionStream::connected(Session& s) { send_position(s, position_lines()); }

void PositionStream::drained() {
  const std::uint64_t departures = gateway_.snapshot().rest_departures;
  if (departures != rest_departures_seen_) {  // the position left a rest: show it at once
    rest_departures_seen_ = departures;
    watch_start_of_motion();
  } else if (start_watch_until_) {  // the loop wakes us each cycle after a departure: changed yet?
    report_start_of_motion();
  }
}

void PositionStream::schedule(std::chrono::microseconds first) {
  // The report timer runs at the fastest rate a client needs (ReportHz, Stream).
  report_timer_.start(first, [this] { return std::chrono::microseconds(static_cast<long>(1e6 / report_timer_hz())); },
                      [this] {
                        if (running_) report_position();
                      });
}

// "AxPos X430.000 Y330.000 C90.000 U0.000 V0.000": every axis by its letter, mm or degrees.
std::string PositionStream::ax_pos_line() const {
  const auto& snap = gateway_.snapshot();
  const auto& layout = gateway_.layout();
  std::string text;
  for (int a = 0; a < layout.count; ++a) {
    if (a) text.push_back(' ');
    text.push_back(layout.letters[a]);
    protocol::append_mm(text, snap.position[a]);
  }
  return protocol::format_event("AxPos", text);
}

}  // namespace imess::net
