// Session: one TCP client. Reads into a capped LineFramer, writes through a bounded queue;
// a client that stops reading is dropped rather than slowing anyone else.
#pragma once
#include <boost/asio.hpp>
#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "imess/net/program_run.hpp"
#include "imess/protocol/line_framer.hpp"

namespace imess::net {

// What the server keeps about a client besides its bytes: name, rights, dead-man, load.
struct ClientInfo {
  std::string name;              // from Hello; empty: "client<N>"
  bool may_control = false;      // host in control.hosts
  bool may_force = false;        // host in control.force_hosts
  bool commanded = false;        // has sent a command (any verb; blank lines are none)
  std::chrono::steady_clock::time_point connected_at{};  // admitted at
  int watch_ms = 0;              // Watch: dead-man interval, 0 = off
  std::chrono::steady_clock::time_point watch_fired_for{};  // last_received() when the dead-man last fired
  std::uint32_t in_flight = 0;   // commands in the motion loop's ring, not yet answered
  std::optional<ProgramUpload> upload;  // Upload: the program's lines until a line '.'
  double stream_hz = 0;          // Stream: this client's position rate; 0 = the shared ReportHz
  std::chrono::steady_clock::time_point stream_due{};  // its next position report at that rate
  std::string sent_curr_cor, sent_ax_pos;  // the position lines it last got
  std::string observe_reason;    // why it may only observe when its host is not the reason (a web page without the token)
};

class Session : public std::enable_shared_from_this<Session> {
 public:
  using Clock = std::chrono::steady_clock;
  using LineHandler = std::function<void(Session&, const protocol::FramedLine&)>;
  using CloseHandler = std::function<void(Session&)>;

  Session(boost::asio::ip::tcp::socket socket, std::uint32_t id, std::size_t max_queue_bytes, LineHandler on_line,
          CloseHandler on_close);

  void start();
  // The client's address when the socket's own peer is not it (the web panel's sessions run
  // over a socket pair: the browser's address).
  void set_peer(const boost::asio::ip::tcp::endpoint& peer);
  void send(std::string line);  // one complete line with its "\n" (events: sent at once)
  // A line formatted once for many clients (broadcasts): every queue holds the same buffer.
  void send(std::shared_ptr<const std::string> line);

  // Replies leave in the order of the requests, even when the motion loop answers later
  // than the io thread: reserve a slot per request, fill it when the answer is known.
  std::uint32_t reserve_reply();
  void fill_reply(std::uint32_t slot, std::string lines);
  // A slot unanswered for `after` (its answer was lost: the event ring overflowed) gets
  // `line` instead, so the replies behind it flow again. Returns how many slots it filled.
  std::size_t expire_replies(Clock::time_point now, Clock::duration after, const std::string& line);
  std::size_t open_replies() const { return replies_.size(); }
  void close_after_flush();     // Quit: finish writing, then close
  // Drop: ignore further input, send `line` (an Err line saying why), close once it is out.
  void drop(std::string line);
  void close(std::string reason = "disconnected");

  std::uint32_t id() const { return id_; }
  const std::string& close_reason() const { return close_reason_; }  // for the log
  bool failed() const { return failed_; }  // closed because handling its line threw
  const std::string& peer() const { return peer_; }        // "address:port"
  const boost::asio::ip::address& address() const { return address_; }
  std::string host() const { return address_.to_string(); }
  bool open() const { return open_; }
  bool dropping() const { return discard_input_; }
  Clock::time_point last_received() const { return last_received_; }   // any bytes, blank lines too
  // For the server's periodic sweep: how long output (ours and the kernel's unacknowledged
  // bytes) has been waiting without the client acknowledging any byte; zero when nothing waits.
  Clock::duration output_stalled_for(Clock::time_point now);
  ClientInfo& info() { return info_; }
  const ClientInfo& info() const { return info_; }

 private:
  void read();
  void handle(const protocol::FramedLine& line);  // on_line_, an exception ending only this session
  void write();
  // Frames `bytes` and handles their lines (up to each LF) while not backlogged; what is left
  // waits in unread_. False when it stopped early (reading then pauses) or the session closed.
  bool take_input(std::string_view bytes);
  // Too many unanswered requests or too many bytes of answers and events waiting (queued to
  // write, or answered and held for order): stop reading for now. Checked after every line.
  bool backlogged() const;
  void resume_reading();

  boost::asio::ip::tcp::socket socket_;
  std::uint32_t id_;
  std::size_t max_queue_bytes_;
  LineHandler on_line_;
  CloseHandler on_close_;
  protocol::LineFramer framer_;
  std::array<char, 4096> buffer_{};
  // Output waiting to be written; shared buffers, so one broadcast line is formatted once
  // and a write in progress keeps its buffers alive even when the session closes.
  std::deque<std::shared_ptr<const std::string>> queue_;
  struct ReplySlot {
    std::uint32_t id;
    std::string text;         // empty: not answered yet
    Clock::time_point since;  // reserved at
  };
  std::deque<ReplySlot> replies_;
  std::size_t reply_bytes_ = 0;  // of the answered slots held behind an unanswered one
  std::string unread_;           // bytes read but not yet framed: they wait while backlogged
  void flush_replies();       // answered slots at the front leave, in order
  std::uint32_t next_slot_ = 1;
  std::size_t queued_bytes_ = 0;
  bool writing_ = false, open_ = true, close_when_flushed_ = false, discard_input_ = false, read_paused_ = false;
  bool failed_ = false;
  std::string peer_, close_reason_;
  boost::asio::ip::address address_;
  Clock::time_point last_received_ = Clock::now();
  std::optional<Clock::time_point> stall_start_;
  std::size_t bytes_written_ = 0;      // handed to the kernel, since the start
  std::size_t last_acknowledged_ = 0;  // bytes_written_ minus the kernel's unacknowledged, at the last sweep
  ClientInfo info_;
};

}  // namespace imess::net
