// Queued moves on the io thread: MoveTo / ArcTo / Dwell become planner requests, final
// segments go into the motion loop's segment ring, Done / Failed come back as events.
// Flush rule: the planner's tail is made final (ending at rest) when the loop holds less than
// kFlushLead of motion — checked after the lines that arrived together, on every Done and
// Failed, and at once when the loop reports QueueLow — so moves sent in one burst are linked
// by look-ahead, and a lone move starts without waiting for a timer.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "imess/net/server.hpp"
#include "imess/net/wording.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

using protocol::ErrorCode;
using protocol::format_err;
using protocol::format_ok;

namespace {
constexpr double kFlushLead = 0.05;  // s of motion the loop should hold before the plan must end at rest

// A number as a person typed it: 2.5, 0, 1e+06.
std::string as_typed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The number of a queued id in an event, and the Failed line.
std::string failed_line(std::uint32_t id, core::FailReason why) {
  auto w = fail_wording(why);
  return protocol::format_event("Failed", std::to_string(id) + " " + std::string(w.name) + " " + std::string(w.text));
}
}  // namespace

bool Server::plan_from_here(std::string& why) {
  if (planning_) return true;
  const auto& snap = core_.snapshot();
  if ((snap.mode != core::Mode::Idle && snap.mode != core::Mode::Free) || !in_loop_.empty()) {
    why = std::string("the machine is busy (State ") + std::string(mode_name(snap.mode)) +
          "); queue moves when it stands, or StopMv";
    return false;
  }
  planner::Pose here{};
  for (int a = 0; a < core::kAxes; ++a) here[a] = snap.position[a];
  planner_.set_position(here);
  planning_ = true;
  return true;
}

void Server::queue_move(Session& s, std::uint32_t slot, std::string_view verb, const planner::Request& r) {
  std::string why;
  if (!plan_from_here(why)) {
    reply(s, slot, format_err(ErrorCode::Busy, why));
    return;
  }
  auto res = planner_.append(r);
  if (!res.ok()) {
    const auto code = res.error == planner::PlanError::OutOfTravel ? ErrorCode::OutOfTravel : ErrorCode::BadValue;
    reply(s, slot, format_err(code, planner::describe(res, planner_.machine())));
    if (unsent_.empty() && in_loop_.empty()) planning_ = false;
    return;
  }
  const std::uint32_t id = std::visit([](const auto& q) { return q.id; }, r);
  unsent_.push_back(id);
  if (config_.log_motion) spdlog::info("client {}: {} {} queued", s.id(), verb, id);
  reply(s, slot, format_ok(std::string(verb)));
  schedule_flush_check();
}

void Server::move_to(Session& s, std::uint32_t slot, const protocol::MoveTo& c) {
  std::string why;
  if (!plan_from_here(why)) {
    reply(s, slot, format_err(ErrorCode::Busy, why));
    return;
  }
  planner::Line l;
  l.id = c.id;
  l.target = planner_.position();
  if (c.words.x) l.target[0] = *c.words.x;
  if (c.words.y) l.target[1] = *c.words.y;
  if (c.words.z) l.target[2] = *c.words.z;
  const auto& p = core_.params();
  l.feed = c.words.f ? *c.words.f : p.goto_speed * p.speed_level;
  queue_move(s, slot, "MoveTo", l);
}

// ArcTo id CW|CCW X Y Z I J K [N i j k] [P] [F]: the end (unnamed axes keep their
// position), the centre at start + (I, J, K) (a missing one is 0). The plane: N when given
// (any orientation; a planar arc, as DirectCMM's MoveInArc), else by the offsets named:
// I J or neither XY, I K ZX, J K YZ (G17 / G18 / G19), where the third axis makes a helix.
// P is LinuxCNC's: the number of turns, P1 the arc alone.
void Server::arc_to(Session& s, std::uint32_t slot, const protocol::ArcTo& c) {
  const auto& w = c.words;
  std::array<double, 3> normal{0, 0, 1};
  if (w.n) {
    normal = *w.n;
  } else if (w.k && w.i && w.j) {
    reply(s, slot, format_err(ErrorCode::BadValue, "ArcTo " + std::to_string(c.id) +
                                                       ": I J K together need N i j k, the plane's normal; "
                                                       "I J is the XY plane, I K the ZX plane, J K the YZ plane"));
    return;
  } else if (w.k && !w.i && !w.j) {
    reply(s, slot, format_err(ErrorCode::BadValue, "ArcTo " + std::to_string(c.id) +
                                                       ": K alone names no plane; give I K (ZX plane) or J K "
                                                       "(YZ plane), with I0 or J0 if need be, or N i j k"));
    return;
  } else if (w.k) {
    normal = w.i ? std::array<double, 3>{0, 1, 0} : std::array<double, 3>{1, 0, 0};
  }
  int turns = 0;
  if (w.p) {
    if (!(*w.p >= 1 && *w.p <= protocol::kMaxArcTurns && *w.p == std::floor(*w.p))) {
      reply(s, slot, format_err(ErrorCode::BadValue, "ArcTo " + std::to_string(c.id) +
                                                         ": P is the number of turns, a whole number from 1 (the arc "
                                                         "alone) to " + std::to_string(protocol::kMaxArcTurns) +
                                                         ", got " + as_typed(*w.p)));
      return;
    }
    turns = static_cast<int>(*w.p) - 1;
  }
  std::string why;
  if (!plan_from_here(why)) {
    reply(s, slot, format_err(ErrorCode::Busy, why));
    return;
  }
  const planner::Pose start = planner_.position();
  planner::Arc a;
  a.id = c.id;
  a.target = start;
  if (w.x) a.target[0] = *w.x;
  if (w.y) a.target[1] = *w.y;
  if (w.z) a.target[2] = *w.z;
  a.centre = {start[0] + w.i.value_or(0), start[1] + w.j.value_or(0), start[2] + w.k.value_or(0)};
  a.normal = normal;
  a.planar = w.n.has_value();
  a.plane_axes = {0, 1, 2};
  a.ccw = c.ccw;
  a.turns = turns;
  const auto& p = core_.params();
  a.feed = w.f ? *w.f : p.goto_speed * p.speed_level;
  queue_move(s, slot, "ArcTo", a);
}

void Server::queue_status(Session& s, std::uint32_t slot) {
  const auto& snap = core_.snapshot();
  const std::size_t pending = unsent_.size() + in_loop_.size();
  reply(s, slot, format_ok("Queue", "Pending " + std::to_string(pending) + " Running " +
                                        (snap.path_running ? std::to_string(snap.path_id) : std::string("none")) +
                                        " Held " + (snap.path_held ? "yes" : "no")));
}

void Server::feed_segments() {
  planner::PlannedSegment seg;
  while (core_.segment_room() > 0 && planner_.take(seg)) {
    if (!core_.submit_segment({seg, core_.stop_ticket(), drops_})) {
      // cannot happen (room was checked, one producer); never lose an id silently
      broadcast(failed_line(seg.id, core::FailReason::Faulted));
      if (!unsent_.empty()) unsent_.pop_front();
      continue;
    }
    if (!unsent_.empty()) unsent_.pop_front();
    in_loop_.emplace_back(seg.id, seg.duration());
  }
}

void Server::schedule_flush_check() {
  if (flush_check_posted_) return;
  flush_check_posted_ = true;
  boost::asio::post(io_, [this] {
    flush_check_posted_ = false;
    flush_check();
  });
}

void Server::flush_check() {
  if (planner_.pending() > 0) {
    double lead = planner_.ready_duration();
    for (const auto& [id, seconds] : in_loop_) lead += seconds;
    if (lead < kFlushLead) planner_.flush();
  }
  feed_segments();
}

void Server::on_segment_end(const core::Event& e) {
  auto it = std::find_if(in_loop_.begin(), in_loop_.end(), [&](const auto& x) { return x.first == e.id; });
  if (it != in_loop_.end()) in_loop_.erase(it);
  if (e.kind == core::EventKind::Done) {
    broadcast(protocol::format_event("Done", std::to_string(e.id)));
    if (config_.log_motion) spdlog::info("move {} done", e.id);
  } else {
    broadcast(failed_line(e.id, e.fail));
    log_limited(spdlog::level::warn, "move-failed", "move " + std::to_string(e.id) + " failed: " +
                                                        std::string(fail_wording(e.fail).name));
  }
  if (unsent_.empty() && in_loop_.empty() && planner_.pending() == 0 && planner_.ready() == 0)
    planning_ = false;  // the queue ran out: the next one starts where the machine stands
  flush_check();
}

void Server::drop_planned(core::FailReason why) {
  for (auto id : unsent_) broadcast(failed_line(id, why));
  unsent_.clear();
  planner::Pose here{};
  planner_.set_position(here);  // discards what was not taken; the next queue starts anew
  planning_ = false;
}

}  // namespace imess::net
