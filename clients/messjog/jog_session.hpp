// JogSession: a JogPanel wired to a self-reconnecting link to messd. No terminal code, so the
// tests run it against a fake daemon; main.cpp adds only keys and drawing.
#pragma once
#include <chrono>

#include "imess/client/reconnector.hpp"
#include "jog_panel.hpp"

namespace imess::messjog {

class JogSession {
 public:
  using Clock = std::chrono::steady_clock;

  JogSession(client::Endpoint where, client::Reconnector::Options options);

  // Starts with a link opened beforehand (messjog fails fast when messd is not there at start).
  void adopt(client::Connection connection);

  // Performs an operator action: sends its command lines, if any.
  void act(JogAction action, Clock::time_point now = Clock::now());

  // Reads what messd sent (without waiting), notices a lost link, reconnects when due.
  void service(Clock::time_point now = Clock::now());

  // Waits up to `timeout` for messd, then service(). For callers without their own poll().
  void pump(std::chrono::milliseconds timeout);

  // Closes the link gracefully, so the last command (StopMv on quit) is never lost to a reset.
  void finish();

  // The descriptor to poll for input (-1 while disconnected) and the longest sensible wait.
  int fd() const;
  std::chrono::milliseconds max_wait(Clock::time_point now = Clock::now()) const;

  JogPanel& panel() { return panel_; }
  const JogPanel& panel() const { return panel_; }
  const client::Reconnector& link() const { return link_; }

 private:
  void connected();
  void send(const std::vector<std::string>& lines, Clock::time_point now = Clock::now());
  void keep_alive(Clock::time_point now);  // a blank line when the dead-man needs one

  client::Reconnector link_;
  JogPanel panel_;
  Clock::time_point last_sent_{};
};

}  // namespace imess::messjog
