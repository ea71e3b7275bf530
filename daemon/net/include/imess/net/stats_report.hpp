// StatsReport: the Stats verb — the motion loop's timing from its LoopRunner (since the start,
// or over an interval a client restarts), and the loop line of the periodic timing log.
#pragma once
#include <boost/asio.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "imess/core/loop_runner.hpp"
#include "imess/net/session_hub.hpp"
#include "imess/protocol/commands.hpp"

namespace imess::net {

class StatsReport {
 public:
  // runner may be null (no timing statistics: Stats then reports zeros).
  // link_errors: the motion loop's published count of the backend's link errors.
  StatsReport(boost::asio::io_context& io, core::LoopRunner* runner, SessionHub& sessions,
              std::function<std::uint64_t()> link_errors)
      : io_(io), runner_(runner), sessions_(sessions), link_errors_(std::move(link_errors)) {}
  void stats(Session& s, std::uint32_t slot, const protocol::Stats& c);
  std::string stats_line();

 private:
  void reply_when_restarted(std::weak_ptr<Session> s, std::uint32_t slot, int waited);

  boost::asio::io_context& io_;
  core::LoopRunner* runner_;
  SessionHub& sessions_;
  std::function<std::uint64_t()> link_errors_;
};

}  // namespace imess::net
