// Reconnector: keeps a Connection to messd alive across daemon restarts, retrying every
// interval. The daemon keeps all machine state, so a client only has to connect again.
#pragma once
#include <chrono>
#include <optional>
#include <string>

#include "imess/client/connection.hpp"

namespace imess::client {

class Reconnector {
 public:
  using Clock = std::chrono::steady_clock;

  struct Options {
    std::chrono::milliseconds retry_interval{1000};
    std::chrono::milliseconds connect_timeout{500};  // short: an attempt blocks the caller
  };

  Reconnector(Endpoint where, Options options);
  explicit Reconnector(Endpoint where) : Reconnector(std::move(where), Options{}) {}

  // Adopts an already open connection (e.g. the first one, opened to fail fast).
  void adopt(Connection connection);

  // When disconnected and the retry interval has passed, tries once.
  // Returns true exactly when this call made a new connection (send your Hello then).
  bool maintain(Clock::time_point now = Clock::now());

  // Marks the link lost (after Closed from a read or a failed send); the next attempt is
  // one interval later.
  void lost(Clock::time_point now = Clock::now());

  bool connected() const { return connection_.has_value() && connection_->is_open(); }
  Connection* connection() { return connected() ? &*connection_ : nullptr; }
  int fd() const { return connected() ? connection_->fd() : -1; }  // for poll(); -1 while down

  // Sends a line if connected; on failure marks the link lost. False when nothing was sent.
  bool send_line(std::string_view line);

  // Time until the next attempt (zero when due or connected), to bound a poll() timeout.
  std::chrono::milliseconds until_next_attempt(Clock::time_point now = Clock::now()) const;

  const Endpoint& endpoint() const { return endpoint_; }
  int attempts() const { return attempts_; }            // failed attempts since the link was lost
  const std::string& last_error() const { return last_error_; }  // why the last attempt or link failed

 private:
  Endpoint endpoint_;
  Options options_;
  std::optional<Connection> connection_;
  Clock::time_point next_attempt_{};
  int attempts_ = 0;
  std::string last_error_;
};

}  // namespace imess::client
