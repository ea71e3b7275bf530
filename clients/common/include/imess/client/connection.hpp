// Connection: one TCP link to messd, read as protocol lines. POSIX sockets + getaddrinfo + poll
// rather than Boost.Asio: every client is a single-threaded loop that also waits on a terminal
// or a signal, and poll() on plain descriptors serves that directly without an io_context.
#pragma once
#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "imess/client/endpoint.hpp"
#include "imess/protocol/line_framer.hpp"

namespace imess::client {

inline constexpr std::chrono::milliseconds kDefaultConnectTimeout{3000};

// Called once per received line, without its terminator; the view lives until the call returns.
using LineHandler = std::function<void(std::string_view line)>;

enum class ReadStatus {
  Idle,         // nothing arrived (timeout)
  Lines,        // bytes arrived (zero or more complete lines were delivered)
  Closed,       // the daemon closed the link or it broke; see close_reason()
  Interrupted,  // a signal interrupted the wait (EINTR); check your flags and call again
};

class Connection {
 public:
  // Connects to each address `where` resolves to, in order, within `timeout` in total.
  // Throws ConnectError. The socket has TCP keep-alive on, so a vanished host is noticed
  // (about 11 s) even while the daemon has nothing to say. Received lines longer than
  // `max_line_length` are cut there: messd's protocol lines are short, an I++ DME answer may
  // be up to 65536 characters (messipp).
  static Connection open(const Endpoint& where,
                         std::chrono::milliseconds timeout = kDefaultConnectTimeout,
                         std::size_t max_line_length = protocol::kMaxLineLength);

  Connection(Connection&& other) noexcept;
  Connection& operator=(Connection&& other) noexcept;
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;
  ~Connection();

  // Sends one line; appends '\n' if missing. Returns false (and closes) when the link is gone.
  bool send_line(std::string_view line);

  // Waits up to `timeout` for input and delivers complete lines. timeout 0 = just check.
  ReadStatus poll_lines(std::chrono::milliseconds timeout, const LineHandler& on_line);

  // Reads what is available now without waiting (after your own poll() said fd() is readable).
  ReadStatus receive(const LineHandler& on_line);

  bool is_open() const { return fd_ >= 0; }
  int fd() const { return fd_; }  // for poll() together with other descriptors; -1 when closed
  const Endpoint& endpoint() const { return endpoint_; }
  const std::string& close_reason() const { return close_reason_; }  // "closed by messd", ...
  void close();

  // Ends the link without losing what was sent last: half-closes (FIN after our data), then
  // reads and discards until messd closes too or `timeout` passes, then closes. A plain close()
  // with unread input makes the kernel send RST, and a peer that gets RST may drop our final
  // StopMv before it has read it. Use it whenever a client exits.
  void finish(std::chrono::milliseconds timeout = std::chrono::milliseconds{500});

 private:
  Connection(int fd, Endpoint where, std::size_t max_line_length)
      : fd_(fd), endpoint_(std::move(where)), framer_(max_line_length) {}
  void lost(std::string reason);

  int fd_ = -1;
  Endpoint endpoint_;
  protocol::LineFramer framer_;
  std::string close_reason_;
};

}  // namespace imess::client
