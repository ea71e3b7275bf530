// DaemonProcess: starts build/bin/messd on a free port as a child process (with its own fresh
// journal directory unless the test passes --journal) and stops it; run_messd_to_exit runs one
// that should refuse to start and keeps its exit status, stdout and stderr;
// LineClient: a plain TCP client for tests — send lines, wait for lines with timeouts.
#pragma once
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace imess::test {

// In a forked child: becomes messd on an ephemeral loopback port, with the test's extra
// arguments; never returns. Without real-time scheduling unless asked for (then messd takes
// SCHED_FIFO and locked memory where it is permitted, as scripts/run does, and runs without
// them where not). `binary`: another messd than the build's (a benchmark's --messd).
[[noreturn]] inline void exec_messd(const std::vector<std::string>& args, bool realtime = false,
                                    const std::string& binary = "") {
  std::string bin = binary.empty() ? std::string(IMESS_BIN_DIR) + "/messd" : binary;
  std::vector<std::string> all{bin, "--port", "0", "--listen", "127.0.0.1"};
  if (!realtime) all.push_back("--no-rt");
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv(bin.c_str(), argv.data());
  _exit(127);
}

#ifdef IMESS_SOURCE_DIR  // the tests' (the benches use this header too)
// tests/e2e/fast-cmm.json, the quick simulated CMM of the end-to-end tests.
inline std::string fast_cmm() { return std::string(IMESS_SOURCE_DIR) + "/tests/e2e/fast-cmm.json"; }
#endif

class DaemonProcess {
 public:
  enum class Scheduling { Plain, RealtimeIfPermitted };
  explicit DaemonProcess(std::vector<std::string> args = {}, Scheduling sched = Scheduling::Plain,
                         const std::string& binary = "") {
    // Parallel tests never share a journal: each daemon gets a new one, removed afterwards.
    if (std::find(args.begin(), args.end(), "--journal") == args.end()) {
      std::string dir = (std::filesystem::temp_directory_path() / "imess-test-journal-XXXXXX").string();
      if (!mkdtemp(dir.data())) throw std::runtime_error("mkdtemp failed");
      own_journal_ = dir;
      args.insert(args.begin(), {"--journal", dir});
      // Part frames beside it (the journal reads only its hits-*.jnl files): never the
      // working directory's messd-frames.json.
      if (std::find(args.begin(), args.end(), "--frames") == args.end())
        args.insert(args.begin(), {"--frames", dir + "/frames.json"});
    }
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe failed");
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      dup2(out[1], STDOUT_FILENO);
      int devnull = open("/dev/null", O_WRONLY);
      if (!std::getenv("IMESS_TEST_DAEMON_LOG")) dup2(devnull, STDERR_FILENO);
      close(out[0]);
      exec_messd(args, sched == Scheduling::RealtimeIfPermitted, binary);
    }
    close(out[1]);
    out_ = fdopen(out[0], "r");
    char line[256];
    // "messd: OK, listening on 127.0.0.1:PORT"
    if (!fgets(line, sizeof line, out_)) throw std::runtime_error("messd did not start (see its stderr)");
    std::string s(line);
    auto colon = s.rfind(':');
    if (s.rfind("messd: OK", 0) != 0 || colon == std::string::npos) throw std::runtime_error("unexpected: " + s);
    port_ = std::stoi(s.substr(colon + 1));
    // "messd: I++ DME on 127.0.0.1:PORT" or "messd: I++ DME off"
    if (fgets(line, sizeof line, out_)) {
      const std::string ipp(line);
      if (const auto c = ipp.rfind(':'); ipp.rfind("messd: I++ DME on", 0) == 0 && c != std::string::npos)
        ipp_port_ = std::stoi(ipp.substr(c + 1));
    }
    // "messd: web panel on http://127.0.0.1:PORT/ (files from DIR)" or "messd: web panel off"
    if (fgets(line, sizeof line, out_)) {
      const std::string web(line);
      const std::string on = "messd: web panel on http://";
      if (web.rfind(on, 0) == 0)
        if (const auto c = web.find(':', on.size()); c != std::string::npos) web_port_ = std::stoi(web.substr(c + 1));
    }
  }
  ~DaemonProcess() {
    stop();
    if (!own_journal_.empty()) {
      std::error_code ec;
      std::filesystem::remove_all(own_journal_, ec);
    }
  }
  DaemonProcess(const DaemonProcess&) = delete;
  DaemonProcess& operator=(const DaemonProcess&) = delete;

  int port() const { return port_; }
  pid_t pid() const { return pid_; }
  int ipp_port() const { return ipp_port_; }  // 0: the I++ DME server is off
  int web_port() const { return web_port_; }  // 0: the web panel is off
  bool running() const { return pid_ > 0 && waitpid(pid_, nullptr, WNOHANG) == 0; }
  const std::string& journal_dir() const { return own_journal_; }  // empty when the test gave --journal
  // Stops with SIGTERM (SIGKILL: as a crash would); returns the exit status.
  int stop(int signal = SIGTERM) {
    if (pid_ <= 0) return status_;
    kill(pid_, signal);
    int st = 0;
    waitpid(pid_, &st, 0);
    pid_ = -1;
    if (out_) fclose(out_);
    out_ = nullptr;
    status_ = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
    return status_;
  }

 private:
  pid_t pid_ = -1;
  FILE* out_ = nullptr;
  int port_ = 0, ipp_port_ = 0, web_port_ = 0, status_ = -1;
  std::string own_journal_;
};

// A messd run that is expected to end by itself (a refused start): exit status and what it
// wrote to stdout and stderr, separately. After timeout_s it is killed (status 128 + 9).
struct MessdExit {
  int status = -1;
  std::string out, err;
};
inline MessdExit run_messd_to_exit(const std::vector<std::string>& args, double timeout_s = 10.0) {
  int out[2], err[2];
  if (pipe(out) != 0 || pipe(err) != 0) throw std::runtime_error("pipe failed");
  pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    dup2(err[1], STDERR_FILENO);
    close(out[0]);
    close(err[0]);
    exec_messd(args);
  }
  close(out[1]);
  close(err[1]);
  MessdExit r;
  pollfd fds[2]{{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
  std::string* texts[2]{&r.out, &r.err};
  auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int open_fds = 2;
  bool killed = false;
  while (open_fds > 0) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      kill(pid, SIGKILL);
      killed = true;
      break;
    }
    if (poll(fds, 2, static_cast<int>(left.count())) <= 0) continue;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      char buf[4096];
      auto n = read(fds[i].fd, buf, sizeof buf);
      if (n > 0) {
        texts[i]->append(buf, static_cast<std::size_t>(n));
      } else {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  for (auto& f : fds)
    if (f.fd >= 0) close(f.fd);
  int st = 0;
  waitpid(pid, &st, 0);
  r.status = killed ? 128 + SIGKILL : WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return r;
}

class LineClient {
 public:
  explicit LineClient(int port) : LineClient(port, {}, 0) {}
  // From a chosen loopback source address (127.0.0.2 …: "another host" on one machine), and
  // with a small receive buffer when rcvbuf > 0 (a client that stops reading fills up soon).
  LineClient(int port, const std::string& source, int rcvbuf) {
    fd_ = socket(AF_INET, SOCK_STREAM, 0);
    if (rcvbuf > 0) setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof rcvbuf);
    if (!source.empty()) {
      sockaddr_in from{};
      from.sin_family = AF_INET;
      inet_pton(AF_INET, source.c_str(), &from.sin_addr);
      if (bind(fd_, reinterpret_cast<sockaddr*>(&from), sizeof from) != 0) throw std::runtime_error("bind failed");
    }
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(static_cast<uint16_t>(port));
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) throw std::runtime_error("connect failed");
    int one = 1;
    setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  }
  ~LineClient() {
    if (fd_ >= 0) close(fd_);
  }
  LineClient(const LineClient&) = delete;
  LineClient& operator=(const LineClient&) = delete;

  void send_raw(const std::string& bytes) {
    std::size_t off = 0;
    while (off < bytes.size()) {
      auto n = ::send(fd_, bytes.data() + off, bytes.size() - off, MSG_NOSIGNAL);
      if (n <= 0) throw std::runtime_error("send failed");
      off += static_cast<std::size_t>(n);
    }
  }
  void send(const std::string& line) { send_raw(line + "\n"); }

  // The next line (without "\n"), or nullopt after timeout_s / on close.
  std::optional<std::string> next(double timeout_s = 5.0) {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    for (;;) {
      auto nl = buf_.find('\n');
      if (nl != std::string::npos) {
        std::string line = buf_.substr(0, nl);
        buf_.erase(0, nl + 1);
        raw_ += line + "\n";
        return line;
      }
      auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return std::nullopt;
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
      char tmp[4096];
      auto n = recv(fd_, tmp, sizeof tmp, 0);
      if (n <= 0) {
        closed_ = true;
        return std::nullopt;
      }
      buf_.append(tmp, static_cast<std::size_t>(n));
    }
  }
  // Reads lines until pred(line) holds; returns that line (nullopt on timeout). Every line
  // read is kept in seen().
  std::optional<std::string> until(const std::function<bool(const std::string&)>& pred, double timeout_s = 10.0) {
    auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    for (;;) {
      double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
      if (left <= 0) return std::nullopt;
      auto l = next(left);
      if (!l) return std::nullopt;
      seen_.push_back(*l);
      if (pred(*l)) return l;
    }
  }
  std::optional<std::string> until_prefix(const std::string& prefix, double timeout_s = 10.0) {
    return until([&](const std::string& l) { return l.rfind(prefix, 0) == 0; }, timeout_s);
  }
  // Sends a command and returns its reply (the first Ok/Err line).
  std::optional<std::string> request(const std::string& line, double timeout_s = 5.0) {
    send(line);
    return until([](const std::string& l) { return l.rfind("Ok ", 0) == 0 || l.rfind("Err ", 0) == 0; }, timeout_s);
  }
  // Closes with a reset (SO_LINGER 0): what a crashed host or a killed NAT entry looks like.
  void reset() {
    linger l{1, 0};
    setsockopt(fd_, SOL_SOCKET, SO_LINGER, &l, sizeof l);
    close(fd_);
    fd_ = -1;
  }
  void close_now() {
    close(fd_);
    fd_ = -1;
  }
  const std::vector<std::string>& seen() const { return seen_; }
  const std::string& raw() const { return raw_; }
  bool closed() const { return closed_; }

 private:
  int fd_ = -1;
  std::string buf_, raw_;
  std::vector<std::string> seen_;
  bool closed_ = false;
};

}  // namespace imess::test
