// PositionStream: CurrCor (and AxPos on a machine whose axes are not exactly X Y Z) to every
// MESSD client whenever its printed position changed since that client last got it — at the
// shared ReportHz, or at the client's own Stream rate up to the motion loop's — and the first
// change after rest at once. Each line is formatted once per tick and shared by every queue.
#pragma once
#include <boost/asio.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "imess/net/motion_gateway.hpp"
#include "imess/net/observers.hpp"
#include "imess/net/periodic_timer.hpp"
#include "imess/net/server_config.hpp"
#include "imess/net/session_hub.hpp"

namespace imess::net {

class PositionStream : public MotionObserver {
 public:
  // on_shared_tick: what else runs at ReportHz (a program's Block, I++ DME move reports).
  PositionStream(boost::asio::io_context& io, ServerConfig& config, MotionGateway& gateway, SessionHub& sessions,
                 std::function<void()> on_shared_tick);
  void start();  // the position as it is now; the report timer (when streaming)
  void stop();
  void connected(Session& s);  // the position on connect; changes only from then on
  std::string set_stream_rate(Session& s, double hz);  // the reply to Stream
  std::string ax_pos_line() const;  // "AxPos X430.000 Y330.000 C90.000 ...": every axis by its letter
  void drained() override;  // after each drain of the loop's events: did the position leave a rest?

 private:
  struct PositionLines {
    std::shared_ptr<const std::string> curr_cor, ax_pos;  // ax_pos: only when the axes are not X Y Z
  };
  PositionLines position_lines() const;
  bool send_position(Session& s, const PositionLines& lines);  // what changed since s last got it
  void report_position();         // the report timer, at the fastest rate a client needs
  void report_start_of_motion();  // the first change after rest, at once (woken by the loop)
  void watch_start_of_motion();   // the loop saw the position leave a rest: poll it until it shows
  double report_timer_hz() const;
  void schedule(std::chrono::microseconds first);

  boost::asio::io_context& io_;
  ServerConfig& config_;
  MotionGateway& gateway_;
  SessionHub& sessions_;
  std::function<void()> on_shared_tick_;
  PeriodicTimer report_timer_;
  bool running_ = false;
  std::optional<std::chrono::steady_clock::time_point> start_watch_until_;  // looking for the first printed change after a rest, until then
  std::uint64_t rest_departures_seen_ = 0;
  std::string last_curr_cor_;
  bool at_rest_ = false;  // the last shared report period changed no position
  std::chrono::steady_clock::time_point shared_report_due_{};  // the next ReportHz tick
  std::string last_ax_pos_;  // AxPos: only on a machine whose axes are not exactly X Y Z
};

}  // namespace imess::net
