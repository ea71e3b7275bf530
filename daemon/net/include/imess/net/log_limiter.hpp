// LogLimiter: at most N log lines per message class per second; what is held back is
// counted and reported once ("... suppressed N similar lines") when the class next speaks.
#pragma once
#include <spdlog/common.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace imess::net {

class LogLimiter {
 public:
  using Clock = std::chrono::steady_clock;
  explicit LogLimiter(int per_second = 5) : per_second_(per_second) {}

  // nullopt: drop this line. A number: log it, after reporting that many suppressed lines
  // of the class (0: none were suppressed).
  std::optional<std::uint64_t> admit(std::string_view message_class, Clock::time_point now);

  // Classes whose window has ended with lines held back, and how many (then forgotten):
  // called periodically, so a flood that stops is still counted in the log.
  std::vector<std::pair<std::string, std::uint64_t>> take_expired(Clock::time_point now);

 private:
  struct Window {
    Clock::time_point start;
    int lines = 0;
    std::uint64_t suppressed = 0;
  };
  int per_second_;
  std::map<std::string, Window, std::less<>> windows_;
};

// Logs through the limiter: at most its lines a second per message class, then the count.
void log_limited(LogLimiter& limiter, spdlog::level::level_enum level, std::string_view message_class, const std::string& text);

}  // namespace imess::net
