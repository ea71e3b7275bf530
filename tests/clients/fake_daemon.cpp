// FakeDaemon: one poll() thread owns every socket; the test thread only queues actions.
#include "fake_daemon.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>

#include "imess/protocol/line_framer.hpp"

namespace imess::test {
namespace {

int listen_on(std::uint16_t port, std::uint16_t& bound) {
  int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  int on = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(port);
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0 || ::listen(fd, 8) != 0) {
    ::close(fd);
    throw std::runtime_error("fake daemon: cannot listen on 127.0.0.1:" + std::to_string(port));
  }
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  bound = ntohs(a.sin_port);
  return fd;
}

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::send(fd, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (n <= 0) return;  // the client went away; its read side notices
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

std::uint16_t unused_port() {
  std::uint16_t port = 0;
  ::close(listen_on(0, port));
  return port;
}

FakeDaemon::FakeDaemon(FakeDaemonScript script) : script_(std::move(script)) {
  listen_fd_ = listen_on(script_.port, port_);
  if (::pipe(wake_) != 0) throw std::runtime_error("fake daemon: pipe");
  thread_ = std::thread([this] { run(); });
}

FakeDaemon::~FakeDaemon() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  char c = 0;
  (void)!::write(wake_[1], &c, 1);
  thread_.join();
  ::close(listen_fd_);
  ::close(wake_[0]);
  ::close(wake_[1]);
}

void FakeDaemon::enqueue(Action action) {
  {
    std::lock_guard lock(mutex_);
    actions_.push_back(std::move(action));
  }
  char c = 0;
  (void)!::write(wake_[1], &c, 1);
}

void FakeDaemon::send(const std::string& line) { enqueue({Action::Send, line + "\n"}); }
void FakeDaemon::send_raw(const std::string& bytes) { enqueue({Action::Send, bytes}); }
void FakeDaemon::drop_clients() { enqueue({Action::Drop, {}}); }

bool FakeDaemon::wait_for_accepted(int count, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] { return accepted_ >= count; });
}

bool FakeDaemon::wait_for_line(const std::string& line, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] {
    for (const auto& l : received_)
      if (l == line) return true;
    return false;
  });
}

std::vector<std::string> FakeDaemon::received() const {
  std::lock_guard lock(mutex_);
  return received_;
}

bool FakeDaemon::wait_for_gone(int count, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] { return gone_ >= count; });
}

int FakeDaemon::resets() const {
  std::lock_guard lock(mutex_);
  return resets_;
}

int FakeDaemon::accepted() const {
  std::lock_guard lock(mutex_);
  return accepted_;
}

void FakeDaemon::run() {
  struct Client {
    int fd;
    protocol::LineFramer framer;
  };
  std::vector<Client> clients;
  auto close_all = [&] {
    for (auto& c : clients) ::close(c.fd);
    clients.clear();
  };
  for (;;) {
    std::vector<pollfd> fds{{wake_[0], POLLIN, 0}, {listen_fd_, POLLIN, 0}};
    for (auto& c : clients) fds.push_back({c.fd, POLLIN, 0});
    ::poll(fds.data(), fds.size(), -1);

    if (fds[0].revents & POLLIN) {
      char buf[64];
      (void)!::read(wake_[0], buf, sizeof buf);
      std::deque<Action> todo;
      {
        std::lock_guard lock(mutex_);
        if (stop_) break;
        todo.swap(actions_);
      }
      for (auto& a : todo) {
        if (a.kind == Action::Drop) close_all();
        else
          for (auto& c : clients) write_all(c.fd, a.bytes);
      }
    }
    if (fds[1].revents & POLLIN) {
      int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
      if (fd >= 0) {
        for (const auto& line : script_.greeting) write_all(fd, line + "\n");
        clients.push_back({fd, protocol::LineFramer{}});
        std::lock_guard lock(mutex_);
        ++accepted_;
        changed_.notify_all();
      }
    }
    for (std::size_t i = 2; i < fds.size(); ++i) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      auto it = clients.begin();
      while (it != clients.end() && it->fd != fds[i].fd) ++it;
      if (it == clients.end()) continue;  // dropped by an action above
      char buf[4096];
      ssize_t n = ::recv(it->fd, buf, sizeof buf, 0);
      if (n <= 0) {
        bool reset = n < 0 && errno == ECONNRESET;
        ::close(it->fd);
        clients.erase(it);
        std::lock_guard lock(mutex_);
        ++gone_;
        resets_ += reset ? 1 : 0;
        changed_.notify_all();
        continue;
      }
      std::vector<std::string> lines;
      it->framer.feed(std::string_view(buf, static_cast<std::size_t>(n)),
                      [&](const protocol::FramedLine& l) { lines.emplace_back(l.text); });
      for (const auto& line : lines) {
        {
          std::lock_guard lock(mutex_);
          received_.push_back(line);
          changed_.notify_all();
        }
        if (script_.reply)
          for (const auto& r : script_.reply(line)) write_all(it->fd, r + "\n");
      }
    }
  }
  close_all();
}

}  // namespace imess::test
