// Server: the io thread's side of messd — accepts clients on TCP, turns their lines into
// replies or motion-loop commands, and turns motion-loop events into broadcasts.
#pragma once
#include <boost/asio.hpp>
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "imess/core/loop_runner.hpp"
#include "imess/core/motion_core.hpp"
#include "imess/journal/journal.hpp"
#include "imess/net/session.hpp"
#include "imess/protocol/commands.hpp"

namespace imess::net {

struct ServerConfig {
  std::string listen = "0.0.0.0";
  std::uint16_t port = 1066;      // 0: any free port (tests)
  double report_hz = 10;          // CurrCor rate, only when the position changed
  std::size_t max_clients = 100;
  std::size_t max_queue_bytes = 1 << 20;  // per client; beyond it a non-reading client is dropped
  bool log_traffic = false;       // -dc
  bool log_motion = false;        // -dm
  bool log_status = false;        // -dt
  bool log_timing = false;        // -p
  bool beep = true;               // BEL on the console for every point (when it is a terminal)
  std::string version = "0.1.0";
};

class Server {
 public:
  // runner may be null (no timing statistics: Stats then reports zeros). Every measured point
  // is appended to `journal` before any client is sent it.
  Server(boost::asio::io_context& io, ServerConfig config, core::MotionCore& core, core::LoopRunner* runner,
         journal::Journal& journal);
  // Binds and starts accepting; throws std::runtime_error naming the address on failure.
  void start();
  void stop();
  std::uint16_t port() const { return port_; }
  std::size_t clients() const { return sessions_.size(); }

 private:
  // server.cpp
  void accept();
  void broadcast(const std::string& line);
  void send(Session& s, std::string line);    // an event line for one client
  void reply(Session& s, std::uint32_t slot, std::string lines);  // fills a reply slot
  void schedule(boost::asio::steady_timer& t, std::chrono::microseconds every, void (Server::*fn)());
  // dispatch.cpp
  void on_line(Session& s, const protocol::FramedLine& line);
  void on_command(Session& s, std::uint32_t slot, const protocol::Command& cmd);
  bool to_core(Session& s, std::uint32_t slot, core::Command c);
  std::string status_line();
  std::string stats_line();
  // hits.cpp, replay.cpp
  void send_hit(const core::Event& e);
  void on_replay(Session& s, std::uint32_t slot, std::uint64_t from);
  // events.cpp
  void pump_events();
  void report_position();
  void log_periodic();

  boost::asio::io_context& io_;
  ServerConfig config_;
  core::MotionCore& core_;
  core::LoopRunner* runner_;
  journal::Journal& journal_;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer event_timer_, report_timer_, log_timer_;
  std::map<std::uint32_t, std::shared_ptr<Session>> sessions_;
  std::uint32_t next_id_ = 1;
  std::uint16_t port_ = 0;
  std::string last_curr_cor_;
  std::uint64_t points_ = 0;
  bool running_ = false;
};

}  // namespace imess::net
