// A per-class one-second window, so a flooding client cannot fill the disk with log lines.
#include "imess/net/log_limiter.hpp"

#include <spdlog/spdlog.h>

namespace imess::net {

std::optional<std::uint64_t> LogLimiter::admit(std::string_view message_class, Clock::time_point now) {
  auto it = windows_.find(message_class);
  if (it == windows_.end()) it = windows_.emplace(std::string(message_class), Window{now}).first;
  Window& w = it->second;
  if (now - w.start >= std::chrono::seconds(1)) {
    w.start = now;
    w.lines = 0;
  }
  if (w.lines >= per_second_) {
    ++w.suppressed;
    return std::nullopt;
  }
  ++w.lines;
  auto held = w.suppressed;
  w.suppressed = 0;
  return held;
}

std::vector<std::pair<std::string, std::uint64_t>> LogLimiter::take_expired(Clock::time_point now) {
  std::vector<std::pair<std::string, std::uint64_t>> out;
  for (auto& [name, w] : windows_)
    if (w.suppressed > 0 && now - w.start >= std::chrono::seconds(1)) {
      out.emplace_back(name, w.suppressed);
      w.suppressed = 0;
    }
  return out;
}

void log_limited(LogLimiter& limiter, spdlog::level::level_enum level, std::string_view message_class, const std::string& text) {
  auto held = limiter.admit(message_class, LogLimiter::Clock::now());
  if (!held) return;
  if (*held > 0) spdlog::log(level, "... suppressed {} similar '{}' lines", *held, message_class);
  spdlog::log(level, "{}", text);
}

}  // namespace imess::net
