// JogSession: the panel's lines go out, messd's lines come in, the link heals itself.
#include "jog_session.hpp"

#include <poll.h>

#include <algorithm>

namespace imess::messjog {

JogSession::JogSession(client::Endpoint where, client::Reconnector::Options options)
    : link_(std::move(where), options) {}

void JogSession::adopt(client::Connection connection) {
  link_.adopt(std::move(connection));
  connected();
}

void JogSession::connected() { send(panel_.on_connected(link_.endpoint().to_string())); }

void JogSession::send(const std::vector<std::string>& lines, Clock::time_point now) {
  if (!lines.empty()) last_sent_ = now;
  for (const auto& line : lines) {
    if (link_.send_line(line)) continue;
    panel_.on_disconnected(link_.last_error());
    return;
  }
}

void JogSession::act(JogAction action, Clock::time_point now) { send(panel_.act(action, now), now); }

void JogSession::keep_alive(Clock::time_point now) {
  if (!link_.connected() || now - last_sent_ < panel_.keepalive_interval()) return;
  send({""}, now);  // a blank line: no reply, but messd's dead-man (Watch) counts it
}

void JogSession::service(Clock::time_point now) {
  if (auto* c = link_.connection()) {
    auto status = c->receive([&](std::string_view line) { panel_.on_line(line); });
    if (status == client::ReadStatus::Closed) {
      link_.lost(now);
      panel_.on_disconnected(link_.last_error());
    }
  }
  if (link_.maintain(now)) connected();
  keep_alive(now);
}

void JogSession::pump(std::chrono::milliseconds timeout) {
  int fd_now = fd();
  auto wait = std::min(timeout, max_wait());
  if (fd_now >= 0) {
    pollfd p{fd_now, POLLIN, 0};
    ::poll(&p, 1, static_cast<int>(wait.count()));
  } else {
    ::poll(nullptr, 0, static_cast<int>(wait.count()));
  }
  service();
}

void JogSession::finish() {
  if (auto* c = link_.connection()) c->finish();
}

int JogSession::fd() const { return link_.fd(); }

std::chrono::milliseconds JogSession::max_wait(Clock::time_point now) const {
  if (link_.connected()) {
    auto until_keepalive = std::chrono::duration_cast<std::chrono::milliseconds>(last_sent_ + panel_.keepalive_interval() - now);
    return std::clamp(until_keepalive, std::chrono::milliseconds{0}, std::chrono::milliseconds{1000});
  }
  return link_.until_next_attempt(now);
}

}  // namespace imess::messjog
