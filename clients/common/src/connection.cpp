// Connection: non-blocking connect with a deadline, line reception through LineFramer,
// and loss detection (EOF, socket errors, failed sends, TCP keep-alive).
#include "imess/client/connection.hpp"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <memory>

#include "imess/client/connect_error.hpp"

namespace imess::client {
namespace {

using Clock = std::chrono::steady_clock;

std::string error_text(int err) {
  std::string s = std::strerror(err);
  if (!s.empty()) s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
  return s;
}

int remaining_ms(Clock::time_point deadline) {
  auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return left > 0 ? static_cast<int>(left) : 0;
}

void set_keepalive(int fd) {
  int on = 1, idle = 5, interval = 2, count = 3;  // a dead peer is noticed after ~11 s
  setsockopt(fd, SOL_SOCKET, SO_KEEPALIVE, &on, sizeof on);
  setsockopt(fd, IPPROTO_TCP, TCP_KEEPIDLE, &idle, sizeof idle);
  setsockopt(fd, IPPROTO_TCP, TCP_KEEPINTVL, &interval, sizeof interval);
  setsockopt(fd, IPPROTO_TCP, TCP_KEEPCNT, &count, sizeof count);
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);  // jog commands are tiny and urgent
}

// Connects fd (non-blocking) to addr by the deadline. Returns 0 or an errno value.
int connect_by(int fd, const addrinfo& addr, Clock::time_point deadline) {
  if (::connect(fd, addr.ai_addr, addr.ai_addrlen) == 0) return 0;
  if (errno != EINPROGRESS) return errno;
  pollfd p{fd, POLLOUT, 0};
  for (;;) {
    int n = ::poll(&p, 1, remaining_ms(deadline));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    if (n == 0) return ETIMEDOUT;
    int err = 0;
    socklen_t len = sizeof err;
    if (getsockopt(fd, SOL_SOCKET, SO_ERROR, &err, &len) < 0) return errno;
    return err;
  }
}

}  // namespace

Connection Connection::open(const Endpoint& where, std::chrono::milliseconds timeout, std::size_t max_line_length) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_NUMERICSERV;
  addrinfo* found = nullptr;
  std::string port = std::to_string(where.port);
  if (int rc = ::getaddrinfo(where.host.c_str(), port.c_str(), &hints, &found); rc != 0)
    throw ConnectError(where, ConnectError::Kind::NotResolved,
                       rc == EAI_SYSTEM ? error_text(errno) : ::gai_strerror(rc));
  std::unique_ptr<addrinfo, decltype(&::freeaddrinfo)> list(found, &::freeaddrinfo);

  auto deadline = Clock::now() + timeout;
  int last_error = ECONNREFUSED;
  for (addrinfo* a = found; a != nullptr; a = a->ai_next) {
    int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) {
      last_error = errno;
      continue;
    }
    last_error = connect_by(fd, *a, deadline);
    if (last_error == 0) {
      set_keepalive(fd);
      return Connection(fd, where, max_line_length);
    }
    ::close(fd);
    if (last_error == ETIMEDOUT) break;  // the whole budget is spent
  }
  std::string reason = last_error == ETIMEDOUT
                           ? "timed out after " + std::to_string(timeout.count()) + " ms"
                           : error_text(last_error);
  throw ConnectError(where, ConnectError::Kind::Unreachable, reason);
}

Connection::Connection(Connection&& other) noexcept
    : fd_(other.fd_),
      endpoint_(std::move(other.endpoint_)),
      framer_(std::move(other.framer_)),
      close_reason_(std::move(other.close_reason_)) {
  other.fd_ = -1;
}

Connection& Connection::operator=(Connection&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = other.fd_;
    other.fd_ = -1;
    endpoint_ = std::move(other.endpoint_);
    framer_ = std::move(other.framer_);
    close_reason_ = std::move(other.close_reason_);
  }
  return *this;
}

Connection::~Connection() { close(); }

void Connection::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void Connection::finish(std::chrono::milliseconds timeout) {
  if (fd_ < 0) return;
  ::shutdown(fd_, SHUT_WR);
  auto deadline = Clock::now() + timeout;
  char buf[4096];
  for (;;) {
    pollfd p{fd_, POLLIN, 0};
    int n = ::poll(&p, 1, remaining_ms(deadline));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    ssize_t got = ::recv(fd_, buf, sizeof buf, 0);
    if (got < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (got <= 0) break;  // messd closed its side (or the link broke): done
  }
  close_reason_ = "closed by this client";
  close();
}

void Connection::lost(std::string reason) {
  close_reason_ = std::move(reason);
  close();
}

bool Connection::send_line(std::string_view line) {
  if (fd_ < 0) return false;
  std::string out(line);
  if (out.empty() || out.back() != '\n') out.push_back('\n');
  std::size_t sent = 0;
  auto deadline = Clock::now() + std::chrono::seconds(2);  // a daemon that stops reading is lost
  while (sent < out.size()) {
    ssize_t n = ::send(fd_, out.data() + sent, out.size() - sent, MSG_NOSIGNAL);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      pollfd p{fd_, POLLOUT, 0};
      if (::poll(&p, 1, remaining_ms(deadline)) == 0) {
        lost("messd stopped reading");
        return false;
      }
      continue;
    }
    lost(n < 0 ? error_text(errno) : "send failed");
    return false;
  }
  return true;
}

ReadStatus Connection::receive(const LineHandler& on_line) {
  if (fd_ < 0) return ReadStatus::Closed;
  char buf[4096];
  bool any = false;
  for (;;) {
    ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
    if (n > 0) {
      any = true;
      framer_.feed(std::string_view(buf, static_cast<std::size_t>(n)),
                   [&](const protocol::FramedLine& l) { on_line(l.text); });
      if (fd_ < 0) return ReadStatus::Closed;  // the handler closed us
      continue;
    }
    if (n == 0) {
      lost("closed by messd");
      return ReadStatus::Closed;
    }
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) return any ? ReadStatus::Lines : ReadStatus::Idle;
    // A daemon that closes while our last lines are still unread in its socket resets the
    // connection instead of ending it: for the user that is the same event.
    lost(errno == ECONNRESET ? "closed by messd (connection reset)" : error_text(errno));
    return ReadStatus::Closed;
  }
}

ReadStatus Connection::poll_lines(std::chrono::milliseconds timeout, const LineHandler& on_line) {
  if (fd_ < 0) return ReadStatus::Closed;
  pollfd p{fd_, POLLIN, 0};
  int n = ::poll(&p, 1, static_cast<int>(timeout.count()));
  if (n < 0 && errno == EINTR) return ReadStatus::Interrupted;
  if (n < 0) {
    lost(error_text(errno));
    return ReadStatus::Closed;
  }
  if (n == 0) return ReadStatus::Idle;
  return receive(on_line);  // POLLIN, POLLHUP and POLLERR all end in recv telling which
}

}  // namespace imess::client
