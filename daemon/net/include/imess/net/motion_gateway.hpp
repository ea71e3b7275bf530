// MotionGateway: the io thread's one door to the motion loop — the single producer of its
// command ring and segment ring and the single consumer of its event ring. It owns the
// planner of queued moves, the ids planned and in the loop, the commands held behind a
// running Probe, and the stop; every event it drains goes out through the observer fan-out.
// Nothing else in daemon/net touches core::MotionCore.
#pragma once
#include <boost/asio/io_context.hpp>
#include <spdlog/spdlog.h>

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "imess/core/motion_core.hpp"
#include "imess/net/log_limiter.hpp"
#include "imess/net/observers.hpp"
#include "imess/planner/planner.hpp"
#include "imess/planner/scan.hpp"
#include "imess/protocol/commands.hpp"

namespace imess::net {

// A queued command on the wire; after an unfinished Probe it waits in the gateway, unplanned
// (its start is the Probe's end, known only after the hit).
using QueuedCommand = std::variant<protocol::MoveTo, protocol::ArcTo, protocol::Dwell, protocol::Probe, protocol::SetOut,
                                   protocol::ScanLine, protocol::ScanCircle>;

// The words of a queued command (nullptr for Dwell, SetOut).
const protocol::PathWords* words_of(const QueuedCommand& c) noexcept;
// The shape of a MESSD scan (gateway_scan.cpp).
planner::ScanShape scan_shape(const protocol::ScanLine& c);
planner::ScanShape scan_shape(const protocol::ScanCircle& c);
// A pose from start with every axis the words name (on this layout) replaced.
planner::Pose target_of(const hal::AxisLayout& layout, const protocol::PathWords& w, const planner::Pose& start) noexcept;

// Why an ArcTo's words make no arc (wherever it starts); empty when they make one.
std::string arc_refusal(const protocol::ArcTo& c);

class MotionGateway {
 public:
  MotionGateway(boost::asio::io_context& io, core::MotionCore& core, Observers& observers, LogLimiter& log, bool log_motion);

  // The machine as the loop publishes it.
  const core::Snapshot& snapshot() const { return core_.snapshot(); }
  const core::CoreConfig& config() const noexcept { return core_.config(); }
  const core::CoreParams& params() const noexcept { return core_.params(); }
  const hal::AxisLayout& layout() const noexcept { return core_.config().layout; }
  planner::Pose pose_of(const core::AxisVec& v) const noexcept;  // the machine's axes of v as a planner pose

  // Commands: into the command ring (false: full), the parameter lane, the stop lane.
  bool submit(const core::Command& c) { return core_.submit(c); }
  void set_param(core::ParamId id, double value) { core_.set_param(id, value); }
  // The stop lane; what was planned fails (dropped), then every observer hears stopped(who).
  void stop(std::string_view who);
  void abandon_plan();  // the stop lane and the drop, without stopped() (a program that failed)

  // Queued moves. The planner continues the queued path while planning(); else the next
  // plan starts where the machine stands (plan_from_here) or where the caller says (start_at).
  bool planning() const noexcept { return planning_; }
  bool plan_from_here(std::string& why);
  void start_at(const planner::Pose& pose);  // discards the planner's tail, planning() unchanged
  void end_plan_if_idle();                   // nothing planned or in the loop: planning() ends
  void set_planning(bool on) noexcept { planning_ = on; }
  // MESSD's queued command from where the plan ends (its id into the queue); refused: the
  // planner's reason, and a plan left empty ends.
  planner::AppendResult queue(const QueuedCommand& c);
  // Behind an unfinished Probe: checked as far as can be, held until its Done.
  std::optional<std::uint32_t> open_probe() const noexcept { return probe_open_; }
  planner::AppendResult hold(const QueuedCommand& c);
  // A scan from the planner's position (planner/scan.hpp): every segment checked before any is
  // appended, so a refused scan leaves nothing behind; its id is queued once. The settings a
  // front end starts from: the motion loop's parameters (ScanDeflection, ScanBand, ScanStep,
  // ScanSpeed × SpeedLevel, ProbeSpeed onto the surface, PrehitDist as the clearance, at least
  // 2 mm), speed given: that instead of ScanSpeed.
  planner::ScanSettings scan_settings(std::optional<double> speed = std::nullopt) const;
  planner::AppendResult plan_scan(std::uint32_t id, const planner::ScanShape& shape, const planner::ScanSettings& settings);
  // A planner request of a front end's own (a program's item, an I++ DME line); its id is queued once.
  planner::AppendResult append(const planner::Request& r);
  void flush() { planner_.flush(); }  // the plan's tail made final: it ends at rest
  void flush_and_feed();        // the same, and into the ring
  void feed_segments();         // final segments into the ring while it has room
  void schedule_flush_check();  // after the lines that arrived together
  const planner::Pose& planned_end() const noexcept { return planner_.position(); }
  const planner::Machine& machine() const noexcept { return planner_.machine(); }
  const planner::PlannerOptions& options() const noexcept { return planner_.options(); }
  bool planner_holds() const noexcept { return planner_.pending() > 0 || planner_.ready() > 0; }
  std::size_t ids_queued() const noexcept { return unsent_.size() + in_loop_.size(); }  // unsent or in the loop
  std::size_t ids_pending() const noexcept { return unsent_.size() + in_loop_.size() + held_.size(); }
  bool loop_holds_segments() const noexcept { return !in_loop_.empty(); }
  std::optional<std::uint32_t> first_in_loop() const noexcept;
  bool in_loop_between(std::uint32_t first, std::uint32_t last) const noexcept;

  // The event ring: drained on every wake-up (and by the backstop timer); how many there were.
  std::size_t pump_events();

 private:
  planner::AppendResult plan(const QueuedCommand& c);  // appended to planner_ from its position
  planner::AppendResult plan_probe(const protocol::Probe& c);
  void plan_held(const core::AxisVec& from);  // after the Probe's Done: plan what waited, from where it ended
  void fail_held(core::FailReason why);
  void flush_check();                     // flush when the loop holds too little motion
  void on_segment_end(const core::Event& e);  // Done / Failed
  void drop_planned(core::FailReason why);    // fail what the loop has not received, plan anew
  void failed_unsent(std::uint32_t id, core::FailReason why);  // to the id's owner
  void failed_held(std::uint32_t id, core::FailReason why);    // to the fallback (MESSD's)
  bool defer_failure(std::uint32_t id, core::FailReason why);  // MESSD's: wait for the ids the loop holds
  void fail_deferred();  // once those have ended: the waiting failures, in queue order

  boost::asio::io_context& io_;
  core::MotionCore& core_;
  Observers& observers_;
  LogLimiter& log_;
  bool log_motion_;
  // unsent_: ids in the planner, not yet in the ring, in order; in_loop_: ids in the ring or
  // the loop's hand with their planned seconds.
  planner::Planner planner_;
  bool planning_ = false;  // planner_ continues the queued path (else: starts where the machine stands)
  std::deque<std::uint32_t> unsent_;
  std::deque<std::pair<std::uint32_t, double>> in_loop_;
  std::uint32_t drops_ = 0;  // the loop's queue drops known here (stamped on every segment)
  std::optional<std::uint32_t> probe_open_;  // a Probe planned whose Done has not come yet
  std::deque<QueuedCommand> held_;           // commands queued after it, unplanned
  bool flush_check_posted_ = false;
  // MESSD's ids failed by a drop while earlier ones were still in the loop, and those earlier ids.
  std::vector<std::pair<std::uint32_t, core::FailReason>> deferred_;
  std::vector<std::uint32_t> deferred_until_;
};

}  // namespace imess::net
