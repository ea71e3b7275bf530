// ClientPool: up to thousands of non-blocking loopback TCP clients served by one thread on
// one epoll set. Every complete line is handed to the current handler together with the
// CLOCK_MONOTONIC time taken right after the read() that brought its last byte returned.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace imess::bench {

class ClientPool {
 public:
  // (client, line without its "\n", arrival ns on CLOCK_MONOTONIC)
  using LineHandler = std::function<void(int, std::string_view, std::int64_t)>;

  ClientPool();
  ~ClientPool();
  ClientPool(const ClientPool&) = delete;
  ClientPool& operator=(const ClientPool&) = delete;

  // Raises RLIMIT_NOFILE's soft limit to hold `descriptors` more (throws naming the limit when
  // the hard limit is too low).
  static void reserve_descriptors(std::size_t descriptors);

  // Starts a non-blocking connect to 127.0.0.1:port; the new client's number. Lines sent
  // before the connection completes wait for it.
  int open(int port);
  // Opens n clients and serves them until every one is connected and has received its first
  // line (messd's CurrCor on connect, bench_echo's greeting). Throws std::runtime_error saying
  // how many made it and why the others did not (a refused connection, Err 208, the timeout).
  std::vector<int> open_ready(int port, int n, double timeout_s = 20.0);
  void close(int client);
  // Closes with a reset (SO_LINGER 0), as a crashed host's connection ends.
  void reset(int client);
  void close_all();

  void send(int client, std::string_view line);  // appends "\n"
  // Serves the sockets for at most timeout_s (0: only what is ready now); the lines read.
  std::size_t poll(double timeout_s);
  // Serves until done() holds (true) or timeout_s passed (false).
  bool run_until(const std::function<bool()>& done, double timeout_s);
  void run_for(double seconds);

  LineHandler on_line;  // may be replaced between polls (and by a handler, for the next line)

  bool is_open(int client) const;
  bool connected(int client) const;
  std::uint64_t lines(int client) const;
  std::size_t open_count() const { return open_count_; }
  int size() const { return static_cast<int>(conns_.size()); }
  // Why a client was closed by the other side or failed (empty while open).
  const std::string& close_reason(int client) const;
  // The last line a client received (for error messages).
  const std::string& last_line(int client) const;

 private:
  struct Conn;
  void handle(int client, std::uint32_t events);
  void read_from(Conn& c, int client);
  void flush(Conn& c, int client);
  void fail(int client, std::string reason);
  void watch(Conn& c, int client, bool want_write);

  int epoll_ = -1;
  std::vector<std::unique_ptr<Conn>> conns_;
  std::size_t open_count_ = 0;
  std::vector<char> buffer_;
};

}  // namespace imess::bench
