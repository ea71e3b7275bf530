// Liveness: is each MESSD client still there? The owner's dead-man (Watch), writers that
// stopped reading, controllers that fell silent, connections that never command, replies the
// loop never gave; and the one housekeeping timer at the earliest deadline that exists (the
// dead-man's, the journal's fdatasync) — none at all when nothing waits. Rules in
// docs/protocol.md, "Control" and "Connections and idle clients".
#pragma once
#include <boost/asio.hpp>

#include <chrono>
#include <optional>
#include <string_view>

#include "imess/journal/journal.hpp"
#include "imess/net/control_service.hpp"
#include "imess/net/motion_gateway.hpp"
#include "imess/net/observers.hpp"
#include "imess/net/periodic_timer.hpp"
#include "imess/net/server_config.hpp"
#include "imess/net/session_hub.hpp"

namespace imess::net {

class Liveness : public MotionObserver {
 public:
  Liveness(boost::asio::io_context& io, const ServerConfig& config, SessionHub& sessions, ControlService& control,
           MotionGateway& gateway, journal::Journal& journal, LogLimiter& log);
  void start();  // the 250 ms sweep
  void stop();
  void arm_housekeeping();  // after a line (a Watch, a new owner) and a hit (the journal's sync)
  void hit(const core::Event&, const JournaledHit&) override { arm_housekeeping(); }

 private:
  void housekeeping();
  std::optional<std::chrono::steady_clock::time_point> watch_deadline() const;
  void check_watch();     // the owner's dead-man, at its deadline
  void check_clients();   // every 250 ms: stalled writers, silent controllers
  void drop(Session& s, std::string_view why);

  const ServerConfig& config_;
  SessionHub& sessions_;
  ControlService& control_;
  MotionGateway& gateway_;
  journal::Journal& journal_;
  LogLimiter& log_;
  boost::asio::steady_timer housekeeping_timer_;
  PeriodicTimer clients_timer_;
  std::optional<std::chrono::steady_clock::time_point> housekeeping_at_;  // the housekeeping timer's deadline, when armed
  bool running_ = false;
};

}  // namespace imess::net
