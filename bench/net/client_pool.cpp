// The epoll loop of the benchmark's clients: non-blocking connects, reads timestamped at
// return, lines split out of each connection's buffer, sends that wait for EPOLLOUT when the
// socket buffer is full.
#include "client_pool.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/epoll.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "clock.hpp"

namespace imess::bench {

struct ClientPool::Conn {
  int fd = -1;
  bool connected = false;
  bool want_write = false;
  std::string in, out;
  std::uint64_t lines = 0;
  std::string reason, last;
};

namespace {
const std::string kEmpty;
std::string errno_text(const char* what) { return std::string(what) + ": " + std::strerror(errno); }
}  // namespace

ClientPool::ClientPool() : buffer_(1 << 16) {
  epoll_ = epoll_create1(EPOLL_CLOEXEC);
  if (epoll_ < 0) throw std::runtime_error(errno_text("epoll_create1"));
}

ClientPool::~ClientPool() {
  close_all();
  ::close(epoll_);
}

void ClientPool::reserve_descriptors(std::size_t descriptors) {
  rlimit lim{};
  if (getrlimit(RLIMIT_NOFILE, &lim) != 0) return;
  const rlim_t needed = descriptors + 64;
  if (lim.rlim_cur >= needed) return;
  if (lim.rlim_max != RLIM_INFINITY && lim.rlim_max < needed)
    throw std::runtime_error("the descriptor limit (RLIMIT_NOFILE, hard " + std::to_string(lim.rlim_max) + ") is below the " +
                             std::to_string(needed) + " this run needs; raise it (ulimit -Hn) or ask for fewer clients");
  lim.rlim_cur = needed;
  if (setrlimit(RLIMIT_NOFILE, &lim) != 0) throw std::runtime_error(errno_text("setrlimit(RLIMIT_NOFILE)"));
}

int ClientPool::open(int port) {
  const int id = static_cast<int>(conns_.size());
  auto c = std::make_unique<Conn>();
  c->fd = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (c->fd < 0) throw std::runtime_error(errno_text("socket"));
  int one = 1;
  setsockopt(c->fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(static_cast<std::uint16_t>(port));
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const int rc = ::connect(c->fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
  if (rc != 0 && errno != EINPROGRESS) {
    const std::string why = errno_text("connect");
    ::close(c->fd);
    throw std::runtime_error(why + " (127.0.0.1:" + std::to_string(port) + ")");
  }
  c->connected = rc == 0;
  epoll_event ev{};
  ev.events = c->connected ? EPOLLIN : EPOLLOUT;
  ev.data.u32 = static_cast<std::uint32_t>(id);
  c->want_write = !c->connected;
  if (epoll_ctl(epoll_, EPOLL_CTL_ADD, c->fd, &ev) != 0) {
    ::close(c->fd);
    throw std::runtime_error(errno_text("epoll_ctl"));
  }
  conns_.push_back(std::move(c));
  ++open_count_;
  return id;
}

std::vector<int> ClientPool::open_ready(int port, int n, double timeout_s) {
  std::vector<int> ids;
  ids.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    ids.push_back(open(port));
    if (i % 64 == 63) poll(0);  // let the first ones complete while the rest are started
  }
  const bool ok = run_until(
      [&] {
        for (int id : ids)
          if (is_open(id) && lines(id) == 0) return false;
        return true;
      },
      timeout_s);
  int ready = 0;
  std::string why;
  for (int id : ids) {
    if (is_open(id) && lines(id) > 0) {
      ++ready;
    } else if (why.empty()) {
      why = !is_open(id) ? close_reason(id) : "no first line within " + std::to_string(timeout_s) + " s";
    }
  }
  if (!ok || ready < n)
    throw std::runtime_error(std::to_string(ready) + " of " + std::to_string(n) + " clients connected to 127.0.0.1:" +
                             std::to_string(port) + "; the first that did not: " + why);
  return ids;
}

void ClientPool::watch(Conn& c, int client, bool want_write) {
  if (c.want_write == want_write) return;
  c.want_write = want_write;
  epoll_event ev{};
  ev.events = EPOLLIN | (want_write ? EPOLLOUT : 0u);
  ev.data.u32 = static_cast<std::uint32_t>(client);
  epoll_ctl(epoll_, EPOLL_CTL_MOD, c.fd, &ev);
}

void ClientPool::close(int client) {
  if (!is_open(client)) return;
  Conn& c = *conns_[static_cast<std::size_t>(client)];
  epoll_ctl(epoll_, EPOLL_CTL_DEL, c.fd, nullptr);
  ::close(c.fd);
  c.fd = -1;
  c.in.clear();
  c.in.shrink_to_fit();
  c.out.clear();
  c.out.shrink_to_fit();
  if (c.reason.empty()) c.reason = "closed by the bench";
  --open_count_;
}

void ClientPool::reset(int client) {
  if (!is_open(client)) return;
  linger l{1, 0};
  setsockopt(conns_[static_cast<std::size_t>(client)]->fd, SOL_SOCKET, SO_LINGER, &l, sizeof l);
  close(client);
}

void ClientPool::close_all() {
  for (int i = 0; i < size(); ++i) close(i);
}

void ClientPool::fail(int client, std::string reason) {
  Conn& c = *conns_[static_cast<std::size_t>(client)];
  if (c.reason.empty()) c.reason = std::move(reason);
  close(client);
}

void ClientPool::send(int client, std::string_view line) {
  if (!is_open(client)) return;
  Conn& c = *conns_[static_cast<std::size_t>(client)];
  c.out.append(line);
  c.out.push_back('\n');
  if (c.connected) flush(c, client);
}

void ClientPool::flush(Conn& c, int client) {
  while (!c.out.empty()) {
    const ssize_t n = ::send(c.fd, c.out.data(), c.out.size(), MSG_NOSIGNAL);
    if (n > 0) {
      c.out.erase(0, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      watch(c, client, true);
      return;
    }
    if (n < 0 && errno == EINTR) continue;
    fail(client, errno_text("send"));
    return;
  }
  watch(c, client, false);
}

void ClientPool::read_from(Conn& c, int client) {
  for (;;) {
    const ssize_t n = ::read(c.fd, buffer_.data(), buffer_.size());
    const std::int64_t t = mono_ns();  // the moment the bytes reached this program
    if (n == 0) {
      std::string why = "closed by the server";
      if (!c.last.empty()) why += " after '" + c.last.substr(0, 120) + "'";
      fail(client, why);
      return;
    }
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno != EAGAIN && errno != EWOULDBLOCK) fail(client, errno_text("read"));
      return;
    }
    c.in.append(buffer_.data(), static_cast<std::size_t>(n));
    std::size_t start = 0;
    for (;;) {
      const std::size_t nl = c.in.find('\n', start);
      if (nl == std::string::npos) break;
      std::string_view line(c.in.data() + start, nl - start);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      ++c.lines;
      c.last.assign(line);
      if (on_line) on_line(client, line, t);
      if (c.fd < 0) return;  // the handler closed it
      start = nl + 1;
    }
    c.in.erase(0, start);
    if (static_cast<std::size_t>(n) < buffer_.size()) return;  // drained (level-triggered: more wakes us again)
  }
}

void ClientPool::handle(int client, std::uint32_t events) {
  if (!is_open(client)) return;
  Conn& c = *conns_[static_cast<std::size_t>(client)];
  if (!c.connected) {
    int err = 0;
    socklen_t len = sizeof err;
    getsockopt(c.fd, SOL_SOCKET, SO_ERROR, &err, &len);
    if (err != 0) {
      errno = err;
      fail(client, errno_text("connect"));
      return;
    }
    c.connected = true;
    flush(c, client);  // what was sent meanwhile; switches the watch to reading
    if (!is_open(client)) return;
    watch(c, client, !c.out.empty());
    return;
  }
  if (events & (EPOLLIN | EPOLLHUP | EPOLLERR)) read_from(c, client);
  if (is_open(client) && (events & EPOLLOUT)) flush(c, client);
}

std::size_t ClientPool::poll(double timeout_s) {
  epoll_event events[256];
  const int ms = timeout_s <= 0 ? 0 : static_cast<int>(std::ceil(timeout_s * 1000));
  const int n = epoll_wait(epoll_, events, 256, ms);
  if (n < 0) {
    if (errno == EINTR) return 0;
    throw std::runtime_error(errno_text("epoll_wait"));
  }
  std::size_t handled = 0;
  for (int i = 0; i < n; ++i) {
    const int client = static_cast<int>(events[i].data.u32);
    const auto before = lines(client);
    handle(client, events[i].events);
    handled += lines(client) - before;
  }
  return handled;
}

bool ClientPool::run_until(const std::function<bool()>& done, double timeout_s) {
  const std::int64_t deadline = mono_ns() + static_cast<std::int64_t>(timeout_s * 1e9);
  for (;;) {
    if (done()) return true;
    const std::int64_t left = deadline - mono_ns();
    if (left <= 0) return done();
    poll(std::min(ns_to_s(left), 0.05));
  }
}

void ClientPool::run_for(double seconds) {
  run_until([] { return false; }, seconds);
}

bool ClientPool::is_open(int client) const {
  return client >= 0 && client < size() && conns_[static_cast<std::size_t>(client)]->fd >= 0;
}
bool ClientPool::connected(int client) const { return is_open(client) && conns_[static_cast<std::size_t>(client)]->connected; }
std::uint64_t ClientPool::lines(int client) const {
  return client >= 0 && client < size() ? conns_[static_cast<std::size_t>(client)]->lines : 0;
}
const std::string& ClientPool::close_reason(int client) const {
  return client >= 0 && client < size() ? conns_[static_cast<std::size_t>(client)]->reason : kEmpty;
}
const std::string& ClientPool::last_line(int client) const {
  return client >= 0 && client < size() ? conns_[static_cast<std::size_t>(client)]->last : kEmpty;
}

}  // namespace imess::bench
