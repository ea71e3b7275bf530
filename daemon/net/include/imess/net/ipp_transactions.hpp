// IppTransactions: the I++ DME server's connection and transaction rules (docs/ippdme.md,
// "Server") — one client at a time, CR LF lines, Ack on receipt, the normal queue run in
// order (one command at a time), the fast queue answered at once, the error state and 0514,
// and the last-resort guard. What a command does is the IppServer's (execute, execute_fast,
// end_session); this part knows only tags, queues and the socket.
#pragma once
#include <boost/asio.hpp>

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "imess/ippdme/format.hpp"
#include "imess/ippdme/line_framer.hpp"
#include "imess/ippdme/parser.hpp"
#include "imess/net/host_list.hpp"
#include "imess/net/ipp_config.hpp"

namespace imess::net {

class IppTransactions {
 public:
  IppTransactions(boost::asio::io_context& io, const HostList& hosts, IppConfig config);
  virtual ~IppTransactions() = default;
  void stop();
  std::uint16_t port() const { return port_; }
  bool connected() const { return conn_ != nullptr; }
  // The last resort: an exception from `f` (a line, a queued command, a hook the observer
  // fan-out calls) ends the session — logged, E0000 0511, the connection closed — never the
  // daemon. False when it did.
  bool guarded(std::string_view what, const std::function<void()>& f);

 protected:
  struct Connection;
  struct Pending {
    ippdme::Tag tag;
    ippdme::Command command;
    bool aborted = false;  // an error came while a move ran: 0006 when its turn comes, after that move's `%`
    std::size_t bytes = 0;  // its line's length while its Ack waits
    // A line the library refused (its tag readable): acknowledged like a command, answered
    // with this error in its turn (docs/ippdme.md, "Lines the library refuses").
    std::optional<std::pair<ippdme::ErrorCode, std::string>> refused;
  };
  enum class Step : unsigned char { None, Wait, GoTo, PtMeas, Retract, Home, Reset, Scan };

  // What the server does with a command: answered at once (true) or started (false: a motion
  // step); a fast one (event tags); the session's end (EndSession, the connection gone).
  virtual bool execute(const Pending& p) = 0;
  virtual void execute_fast(const Pending& p) = 0;
  virtual void end_session(bool dropped) = 0;

  // ipp_server.cpp: connections, lines, queues, error state
  void accept();
  void read();
  void write();
  void send(std::string bytes);
  void closed();
  void on_line(const ippdme::FramedLine& line);
  void pump();                                  // runs the normal queue's front while it can
  void finish(const ippdme::Tag& tag);          // the `%`, the tag closed
  void fail(const ippdme::Tag& tag, ippdme::ErrorCode code, std::string_view cause);  // `!` + `%`
  void enter_error(ippdme::ErrorCode code, std::string_view cause);
  void abort_queued();
  bool run_front();                             // the queue's front: answered (true) or a motion step started
  void answer_aborted(const Pending& p);        // 0006 and its `%`
  static std::string_view cause_of(const Pending& p);  // F3: the method, or what a refused line began with
  void admit_unacked(bool all);                          // every queued transaction: 0006 + `%`

  boost::asio::io_context& io_;
  const HostList& hosts_;  // control.hosts: who may connect (and so control the machine)
  IppConfig config_;
  boost::asio::ip::tcp::acceptor acceptor_;
  std::uint16_t port_ = 0;
  std::shared_ptr<Connection> conn_;
  ippdme::TagTracker tags_;
  std::deque<Pending> queue_;
  std::deque<Pending> unacked_;  // received while queue_ was full: not acknowledged yet
  std::size_t unacked_bytes_ = 0;
  bool running_ = false;       // the queue's front has started and not finished
  bool in_session_ = false, error_state_ = false;
  std::optional<std::pair<ippdme::ErrorCode, std::string>> last_error_;  // what put the session into the error state
  Step step_ = Step::None;     // the motion step of the queue's front
};

}  // namespace imess::net
