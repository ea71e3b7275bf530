// FakeDaemon: a scripted stand-in for messd on a loopback port, for client tests. A thread
// accepts clients, greets each with fixed lines, answers by a reply function, records every
// line it receives, and sends or drops on request (in request order).
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace imess::test {

using namespace std::chrono_literals;

struct FakeDaemonScript {
  std::uint16_t port = 0;              // 0: any free loopback port
  std::vector<std::string> greeting;   // sent to each client on accept
  std::function<std::vector<std::string>(const std::string& line)> reply;  // per received line
};

class FakeDaemon {
 public:
  explicit FakeDaemon(FakeDaemonScript script = {});
  ~FakeDaemon();  // closes every connection and the listening socket
  FakeDaemon(const FakeDaemon&) = delete;
  FakeDaemon& operator=(const FakeDaemon&) = delete;

  std::uint16_t port() const { return port_; }
  std::string address() const { return "127.0.0.1:" + std::to_string(port_); }

  void send(const std::string& line);      // to every connected client, '\n' appended
  void send_raw(const std::string& bytes); // exactly these bytes (to split a line)
  void drop_clients();                     // close every client connection

  bool wait_for_accepted(int count, std::chrono::milliseconds timeout = 3s);
  bool wait_for_line(const std::string& line, std::chrono::milliseconds timeout = 3s);
  std::vector<std::string> received() const;
  int accepted() const;
  // Clients that went away: by an orderly close (EOF) or by a reset (RST, ECONNRESET).
  bool wait_for_gone(int count, std::chrono::milliseconds timeout = 3s);
  int resets() const;

 private:
  struct Action {
    enum Kind { Send, Drop } kind;
    std::string bytes;
  };
  void run();
  void enqueue(Action action);

  FakeDaemonScript script_;
  int listen_fd_ = -1;
  int wake_[2] = {-1, -1};
  std::uint16_t port_ = 0;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Action> actions_;
  std::vector<std::string> received_;
  int accepted_ = 0;
  int gone_ = 0;
  int resets_ = 0;
  bool stop_ = false;
  std::thread thread_;
};

// A loopback port nobody listens on (bound, read and released), for "connection refused".
std::uint16_t unused_port();

}  // namespace imess::test
