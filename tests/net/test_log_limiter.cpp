// LogLimiter: a flood of one message class yields at most N lines a second plus one count.
#include <catch2/catch.hpp>

#include "imess/net/log_limiter.hpp"

using imess::net::LogLimiter;
using namespace std::chrono_literals;

TEST_CASE("LogLimiter: N lines per class and second, then a count of what was held back") {
  LogLimiter limiter(3);
  auto t0 = LogLimiter::Clock::time_point{} + 100s;
  int logged = 0;
  for (int i = 0; i < 1000; ++i)
    if (limiter.admit("set", t0 + std::chrono::microseconds(i))) ++logged;
  CHECK(logged == 3);
  auto next = limiter.admit("set", t0 + 1s);  // a new second: the count comes first
  REQUIRE(next);
  CHECK(*next == 997);
  CHECK(*limiter.admit("set", t0 + 1s + 1ms) == 0);  // reported once only
}

TEST_CASE("LogLimiter: classes are limited independently") {
  LogLimiter limiter(1);
  auto t0 = LogLimiter::Clock::time_point{} + 5s;
  CHECK(limiter.admit("accept", t0));
  CHECK_FALSE(limiter.admit("accept", t0 + 1ms));
  CHECK(limiter.admit("connect", t0 + 1ms));  // another class still speaks
}

TEST_CASE("LogLimiter: a flood that stops is still counted once its second is over") {
  LogLimiter limiter(2);
  auto t0 = LogLimiter::Clock::time_point{} + 9s;
  for (int i = 0; i < 50; ++i) limiter.admit("refused", t0 + std::chrono::milliseconds(i));
  CHECK(limiter.take_expired(t0 + 500ms).empty());  // the window is still open
  auto expired = limiter.take_expired(t0 + 1s);
  REQUIRE(expired.size() == 1);
  CHECK(expired[0].first == "refused");
  CHECK(expired[0].second == 48);
  CHECK(limiter.take_expired(t0 + 2s).empty());  // reported once
}
