// Server: messd's io side put together — the services every front end shares (MotionGateway,
// ControlService, HitService, FrameService, ProgramRunner, PositionStream) and the front ends
// on them (the MESSD line protocol on TCP 1066: SessionHub, MessdDispatch, MessdEvents; I++
// DME on TCP 1294: IppServer), wired through one observer fan-out. docs/architecture.md.
#pragma once
#include <boost/asio.hpp>

#include <cstdint>
#include <memory>
#include <optional>

#include "imess/core/event_fd.hpp"
#include "imess/core/loop_runner.hpp"
#include "imess/core/motion_core.hpp"
#include "imess/journal/journal.hpp"
#include "imess/net/control_service.hpp"
#include "imess/net/frame_service.hpp"
#include "imess/net/frame_verbs.hpp"
#include "imess/net/hit_service.hpp"
#include "imess/net/ipp_events.hpp"
#include "imess/net/ipp_server.hpp"
#include "imess/net/liveness.hpp"
#include "imess/net/log_limiter.hpp"
#include "imess/net/messd_dispatch.hpp"
#include "imess/net/messd_events.hpp"
#include "imess/net/motion_gateway.hpp"
#include "imess/net/observers.hpp"
#include "imess/net/periodic_timer.hpp"
#include "imess/net/position_stream.hpp"
#include "imess/net/program_runner.hpp"
#include "imess/net/server_config.hpp"
#include "imess/net/session_hub.hpp"
#include "imess/net/stats_report.hpp"
#include "imess/net/web_server.hpp"

namespace imess::net {

class Server {
 public:
  // runner may be null (no timing statistics: Stats then reports zeros). Every measured point
  // is appended to `journal` before any client is sent it. wake: the EventFd the core
  // notifies (core.set_event_signal), or null: events are then drained by the backstop timer.
  Server(boost::asio::io_context& io, ServerConfig config, core::MotionCore& core, core::LoopRunner* runner,
         journal::Journal& journal, core::EventFd* wake = nullptr);
  // Binds and starts accepting; throws std::runtime_error naming the address on failure.
  void start();
  void stop();
  std::uint16_t port() const { return sessions_.port(); }
  std::size_t clients() const { return sessions_.size(); }
  // The I++ DME listener's port (0: off: the configuration turned it off, or the machine has
  // no linear X Y Z) and whether its one client is connected.
  std::uint16_t ipp_port() const { return ipp_ ? ipp_->port() : 0; }
  bool ipp_connected() const { return ipp_ && ipp_->connected(); }
  // The web panel's port (0: off) and the folder its files come from.
  std::uint16_t web_port() const { return web_ ? web_->port() : 0; }
  std::string web_root() const { return web_ ? web_->root() : std::string(); }
  // The I++ move reports (OnMoveReportE): the report timer calls it; the golden harness,
  // whose position stream is off, every motion cycle in virtual time.
  void move_reports();

 private:
  void add_observers();    // in the order clients see lines: journal, MESSD, I++ DME, program, stream
  void wait_for_events();  // re-arms the wait on the EventFd
  void backstop_events();  // the slow timer: counts the events only it found
  void log_periodic();

  boost::asio::io_context& io_;
  ServerConfig config_;
  journal::Journal& journal_;
  core::EventFd* wake_;
  std::optional<boost::asio::posix::stream_descriptor> wake_wait_;  // a dup of wake_'s fd
  LogLimiter log_limiter_;
  Observers observers_;
  // The services.
  MotionGateway gateway_;
  FrameService frames_;
  ProgramRunner programs_;
  ControlService control_;
  HitService hits_;
  // The MESSD front end.
  SessionHub sessions_;
  PositionStream stream_;
  Liveness liveness_;
  StatsReport stats_;
  FrameVerbs frame_verbs_;
  MessdEvents events_;
  MessdDispatch dispatch_;
  // The I++ DME front end (none: turned off, or no linear X Y Z).
  std::unique_ptr<IppServer> ipp_;
  std::unique_ptr<IppEvents> ipp_events_;  // it as an observer
  // The web panel (none: turned off): MESSD sessions over WebSockets, so no observer of its own.
  std::unique_ptr<WebServer> web_;
  PeriodicTimer event_timer_, log_timer_;
  bool running_ = false;
  std::uint64_t woken_ = 0, backstop_found_ = 0;  // drains by wake-up / events only the backstop found
};

}  // namespace imess::net
