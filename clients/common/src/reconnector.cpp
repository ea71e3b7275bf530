// Reconnector: one connection attempt per retry interval while the link is down.
#include "imess/client/reconnector.hpp"

#include "imess/client/connect_error.hpp"

namespace imess::client {

Reconnector::Reconnector(Endpoint where, Options options)
    : endpoint_(std::move(where)), options_(options) {}

void Reconnector::adopt(Connection connection) {
  connection_.emplace(std::move(connection));
  attempts_ = 0;
}

bool Reconnector::maintain(Clock::time_point now) {
  if (connected() || now < next_attempt_) return false;
  try {
    connection_.emplace(Connection::open(endpoint_, options_.connect_timeout));
    attempts_ = 0;
    return true;
  } catch (const ConnectError& e) {
    ++attempts_;
    last_error_ = e.reason();
    next_attempt_ = now + options_.retry_interval;
    return false;
  }
}

void Reconnector::lost(Clock::time_point now) {
  if (connection_) {
    if (!connection_->close_reason().empty()) last_error_ = connection_->close_reason();
    connection_.reset();
  }
  next_attempt_ = now + options_.retry_interval;
}

bool Reconnector::send_line(std::string_view line) {
  if (!connected()) return false;
  if (connection_->send_line(line)) return true;
  lost();
  return false;
}

std::chrono::milliseconds Reconnector::until_next_attempt(Clock::time_point now) const {
  if (connected() || now >= next_attempt_) return std::chrono::milliseconds{0};
  return std::chrono::ceil<std::chrono::milliseconds>(next_attempt_ - now);
}

}  // namespace imess::client
