// The golden replay: messd's Server and motion core wired as in daemon/app/main.cpp, but the
// harness steps the core in virtual time and runs the io_context until it is quiet between
// steps, so every run of a transcript gives the same lines in the same order.
#include "golden_harness.hpp"

#include <arpa/inet.h>
#include <linux/sockios.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <spdlog/spdlog.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <boost/asio.hpp>
#include <chrono>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "config_rig.hpp"
#include "imess/core/event_fd.hpp"
#include "imess/journal/journal.hpp"
#include "imess/net/server.hpp"
#include "version.hpp"

namespace imess::golden {

namespace {

using WallClock = std::chrono::steady_clock;
// Waiting for the kernel to move bytes across loopback takes microseconds; this bound only
// turns a harness that would hang into a failure with a message.
constexpr auto kWallLimit = std::chrono::seconds(10);
constexpr const char* kClosed = "[connection closed]";

class TempDir {
 public:
  TempDir() {
    path_ = (std::filesystem::temp_directory_path() / "imess-golden-XXXXXX").string();
    if (!mkdtemp(path_.data())) throw std::runtime_error("mkdtemp failed");
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// One test client: a blocking-free loopback TCP socket and what it received so far.
struct Client {
  int fd = -1;
  bool ipp = false;     // on messd's I++ DME port: lines end in CR LF both ways
  std::string pending;  // bytes after the last LF
  bool closed = false;  // by messd (EOF seen) or by the script
  ~Client() {
    if (fd >= 0) ::close(fd);
  }
};

journal::JournalConfig journal_config(journal::JournalConfig c, const std::string& dir) {
  c.dir = dir;  // the configuration's limits, a fresh directory: hit numbers start at 1
  return c;
}

net::ServerConfig server_config(net::ServerConfig c) {
  c.listen = "127.0.0.1";
  c.port = 0;
  c.ippdme.on = true;
  c.ippdme.port = 0;
  c.web.on = false;  // the transcripts speak on 1066 and 1294; the web panel is a 1066 session (tests/net)
  c.stream_position = false;  // its rate is a wall-clock timer; see tests/golden/README.md
  c.version = app::kVersion;
  return c;
}

class Harness {
 public:
  explicit Harness(const std::string& config_path)
      : rig_(config_path),
        journal_(journal_config(rig_.config().journal, dir_.path())),
        server_(io_, server_config(rig_.config().server), rig_.core(), nullptr, journal_, &wake_) {
    rig_.core().set_event_signal(&wake_);
    start_ = rig_.clock().now();
    server_.start();
    if (rig_.config().home_on_start) rig_.core().submit(core::Command{core::CommandKind::Home});  // as messd does
  }
  ~Harness() {
    clients_.clear();
    server_.stop();
    quiet();
  }

  // `from`: empty, a loopback address to connect from, or "ipp": to the I++ DME port.
  void connect(int id, const std::string& from, std::vector<Entry>& out) {
    if (clients_.count(id) && !clients_[id]->closed) throw std::runtime_error("client " + std::to_string(id) + " is connected already");
    auto c = std::make_unique<Client>();
    c->fd = ::socket(AF_INET, SOCK_STREAM, 0);
    c->ipp = from == "ipp";
    if (c->ipp && server_.ipp_port() == 0) throw std::runtime_error("this configuration has no I++ DME server");
    if (!from.empty() && !c->ipp) {
      sockaddr_in a{};
      a.sin_family = AF_INET;
      if (inet_pton(AF_INET, from.c_str(), &a.sin_addr) != 1) throw std::runtime_error("not an IPv4 address: " + from);
      if (::bind(c->fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) throw std::runtime_error("cannot bind " + from);
    }
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(c->ipp ? server_.ipp_port() : server_.port());
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(c->fd, reinterpret_cast<sockaddr*>(&to), sizeof to) != 0) throw std::runtime_error("connect failed");
    int one = 1;
    setsockopt(c->fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    // messd answers every connection with a line (CurrCor, or the Err of a refusal): wait for
    // it, so the accept has happened before the script goes on. The I++ server says nothing
    // to the client it accepts (and an error line to one it refuses).
    const int fd = c->fd;
    const bool ipp = c->ipp, was_connected = server_.ipp_connected();
    clients_[id] = std::move(c);
    wait_until([&] {
      pollfd p{fd, POLLIN, 0};
      return ::poll(&p, 1, 0) > 0 || (ipp && !was_connected && server_.ipp_connected());
    }, "messd to answer the connection of client " + std::to_string(id));
    settle();
    collect(out, false);
  }

  void close(int id, std::vector<Entry>& out) {
    Client& c = client(id);
    ::close(c.fd);
    c.fd = -1;
    c.closed = true;
    settle();
    collect(out, false);
  }

  // Sends a batch of lines (each client's in one write, in script order), lets messd read and
  // answer them, runs one motion cycle (the loop takes commands in its next cycle) and
  // collects everything the clients received.
  void send(const std::vector<Entry>& batch, std::vector<Entry>& out) {
    std::map<int, std::string> bytes;
    std::vector<int> order;
    for (const auto& e : batch) {
      if (!bytes.count(e.client)) order.push_back(e.client);
      bytes[e.client] += e.text + (client(e.client).ipp ? "\r\n" : "\n");
    }
    for (int id : order) {
      Client& c = client(id);
      if (c.closed) throw std::runtime_error("client " + std::to_string(id) + " sends after its connection was closed");
      const std::string& b = bytes[id];
      for (std::size_t off = 0; off < b.size();) {
        auto n = ::send(c.fd, b.data() + off, b.size() - off, MSG_NOSIGNAL);
        if (n <= 0) throw std::runtime_error("client " + std::to_string(id) + ": send failed");
        off += static_cast<std::size_t>(n);
      }
    }
    settle();
    cycle();
    settle();
    collect(out, false);
  }

  void advance(long ms, std::vector<Entry>& out) {
    const auto end = rig_.clock().now() + std::chrono::milliseconds(ms);
    while (rig_.clock().now() < end) {
      cycle();
      quiet();  // settle() without its wait: the clients sent nothing since the last step
      collect(out, true);
    }
  }

  test::ConfigRig& rig() { return rig_; }

  // One motion cycle, then the I++ move reports (a timer in messd; here every cycle, in
  // virtual time).
  void cycle() {
    rig_.cycle();
    server_.move_reports();
  }

  void finish(std::vector<Entry>& out) {
    settle();
    collect(out, false);
  }

 private:
  Client& client(int id) {
    auto it = clients_.find(id);
    if (it == clients_.end()) throw std::runtime_error("client " + std::to_string(id) + " never connected ('+" + std::to_string(id) + "')");
    return *it->second;
  }

  template <class Pred>
  void wait_until(Pred done, const std::string& what) {
    const auto limit = WallClock::now() + kWallLimit;
    while (!done()) {
      quiet();
      if (WallClock::now() > limit) throw std::runtime_error("gave up waiting for " + what);
    }
  }

  // Runs every handler that is ready until none is.
  void quiet() {
    do io_.restart();
    while (io_.poll() > 0);
  }

  // The script's bytes are in messd's socket buffers (acknowledged by the peer: nothing
  // left in flight), and messd handled everything it could.
  void settle() {
    for (auto& [id, c] : clients_) {
      if (c->fd < 0) continue;
      const int fd = c->fd;
      wait_until([fd] {
        int unacked = 0;
        return ioctl(fd, SIOCOUTQ, &unacked) != 0 || unacked == 0;
      }, "messd to receive the bytes of client " + std::to_string(id));
    }
    quiet();
  }

  // Everything received since the last call, client by client (client 1 first); during an
  // advance headed by the virtual time it arrived at.
  void collect(std::vector<Entry>& out, bool stamp) {
    // One poll for all clients first: most motion cycles send nothing (a recv per client
    // per cycle made most of a long replay's system time).
    std::vector<pollfd> ready;
    for (auto& [id, c] : clients_)
      if (c->fd >= 0 && !c->closed) ready.push_back({c->fd, POLLIN, 0});
    if (ready.empty() || ::poll(ready.data(), ready.size(), 0) == 0) return;
    std::vector<Entry> lines;
    for (auto& [id, c] : clients_) {
      if (c->fd < 0 || c->closed) continue;
      char buf[65536];
      for (;;) {
        auto n = ::recv(c->fd, buf, sizeof buf, MSG_DONTWAIT);
        if (n > 0) {
          c->pending.append(buf, static_cast<std::size_t>(n));
          continue;
        }
        if (n == 0) c->closed = true;
        break;
      }
      for (auto nl = c->pending.find('\n'); nl != std::string::npos; nl = c->pending.find('\n')) {
        std::string line = c->pending.substr(0, nl);
        if (c->ipp) {  // the CR of every line is checked here, not written
          if (!line.empty() && line.back() == '\r') line.pop_back();
          else line += " [no CR]";
        }
        lines.push_back({EntryKind::Receive, id, line});
        c->pending.erase(0, nl + 1);
      }
      if (c->closed) {
        if (!c->pending.empty()) lines.push_back({EntryKind::Receive, id, c->pending + " [no line end]"});
        lines.push_back({EntryKind::Receive, id, kClosed});
      }
    }
    if (lines.empty()) return;
    if (stamp) out.push_back({EntryKind::Time, 1, "", (rig_.clock().now() - start_) / std::chrono::milliseconds(1)});
    out.insert(out.end(), lines.begin(), lines.end());
  }

  TempDir dir_;  // first: removed after the journal has closed its files
  test::ConfigRig rig_;
  core::EventFd wake_;
  journal::Journal journal_;
  boost::asio::io_context io_;
  net::Server server_;
  std::map<int, std::unique_ptr<Client>> clients_;
  hal::Nanos start_{};
};

}  // namespace

std::vector<Entry> replay(const std::vector<Entry>& script, const std::string& name) { return replay(script, name, {}); }

std::vector<Entry> replay(const std::vector<Entry>& script, const std::string& name,
                          const std::function<void(test::ConfigRig&)>& inspect) {
  spdlog::set_level(spdlog::level::off);  // messd's log is not part of the transcript
  std::vector<Entry> out;
  std::unique_ptr<Harness> h;
  auto need = [&]() -> Harness& {
    if (!h) throw std::runtime_error(name + ": the first line that is not a comment must be '@ config/<file>.json'");
    return *h;
  };
  for (std::size_t i = 0; i < script.size(); ++i) {
    const Entry& e = script[i];
    if (observed(e)) continue;
    out.push_back(e);
    switch (e.kind) {
      case EntryKind::Comment:
      case EntryKind::Receive:
      case EntryKind::Time:
        break;
      case EntryKind::Config:
        if (h) throw std::runtime_error(name + ": one '@' configuration per transcript");
        h = std::make_unique<Harness>(std::string(IMESS_SOURCE_DIR) + "/" + e.text);
        h->connect(1, "", out);  // client 1 is there from the start
        break;
      case EntryKind::Connect: need().connect(e.client, e.text, out); break;
      case EntryKind::Close: need().close(e.client, out); break;
      case EntryKind::Advance: need().advance(e.ms, out); break;
      case EntryKind::Send: {
        // ">>" lines after it join its step: sent in one go before the machine runs.
        std::vector<Entry> batch{e};
        while (i + 1 < script.size() && script[i + 1].kind == EntryKind::Send && script[i + 1].joined) {
          batch.push_back(script[++i]);
          out.push_back(batch.back());
        }
        need().send(batch, out);
        break;
      }
    }
  }
  if (h) h->finish(out);
  if (h && inspect) inspect(h->rig());
  return out;
}

}  // namespace imess::golden
