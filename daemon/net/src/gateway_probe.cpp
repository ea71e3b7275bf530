// The Probe cycle on the io thread: two planned lines with the Probe's id (the approach at the
// move feed up to PrehitDist before the target, the search at ProbeSpeed up to SearchDist
// beyond it), and the commands queued after a Probe, held unplanned until its Done gives the
// place the cycle ended (the retract from the hit, known only after the hit).
#include <spdlog/spdlog.h>

#include "imess/net/motion_gateway.hpp"
#include "imess/planner/probe.hpp"

namespace imess::net {

namespace {
// Before the start is known: the axes the command names lie within the travel.
planner::AppendResult check_held(const planner::Machine& m, const QueuedCommand& c) {
  const protocol::PathWords* w = words_of(c);
  const std::uint32_t id = std::visit([](const auto& q) { return q.id; }, c);
  if (!w) return {planner::PlanError::None, 0};
  for (int a = 0; a < m.count; ++a)
    if (const auto& named = *w->axis(m.axes[a].letter);
        named && (*named < m.axes[a].travel_min || *named > m.axes[a].travel_max))
      return {planner::PlanError::OutOfTravel, id, static_cast<std::int8_t>(a), *named};
  return {planner::PlanError::None, id};
}
}  // namespace

planner::AppendResult MotionGateway::plan_probe(const protocol::Probe& c) {
  const planner::Pose start = planner_.position();
  const planner::Pose target = target_of(layout(), c.words, start);
  const auto& p = core_.params();
  const auto cycle = planner::probe_cycle(
      c.id, start, target, {p.prehit_distance, p.search_distance, c.words.f.value_or(p.goto_speed * p.speed_level), p.probe_speed});
  if (!cycle) return {planner::PlanError::ProbeNoDirection, c.id};
  // Checked before anything is appended, so a refused Probe leaves no half cycle behind:
  // the whole search lies in the travel (a straight line in a box: its two ends do), both feeds.
  planner::Planner dry(planner_.machine(), planner_.options());
  dry.set_position(start);
  if (cycle->approach)
    if (auto r = dry.append(*cycle->approach); !r.ok()) return r;
  if (auto r = dry.append(cycle->search); !r.ok()) return r;
  if (cycle->approach) planner_.append(*cycle->approach);
  return planner_.append(cycle->search);
}

// Behind an unfinished Probe: checked as far as can be, kept until its Done.
planner::AppendResult MotionGateway::hold(const QueuedCommand& c) {
  auto res = check_held(planner_.machine(), c);
  if (res.ok()) held_.push_back(c);
  return res;
}

// The Probe ended at `from`: what waited is planned from there, up to the next Probe (which
// holds the rest again). One the planner refuses now fails with the planner's reason.
void MotionGateway::plan_held(const core::AxisVec& from) {
  if (held_.empty()) return;
  planner_.set_position(pose_of(from));
  planning_ = true;
  while (!held_.empty() && !probe_open_) {
    const QueuedCommand c = held_.front();
    held_.pop_front();
    auto res = plan(c);
    if (!res.ok()) {
      const bool travel = res.error == planner::PlanError::OutOfTravel;
      log_limited(log_, spdlog::level::warn, "held-refused", planner::describe(res, planner_.machine()));
      failed_held(res.id, travel ? core::FailReason::OutOfTravel : core::FailReason::Refused);
    }
  }
  if (unsent_.empty() && in_loop_.empty() && planner_.pending() == 0 && planner_.ready() == 0) planning_ = false;
}

void MotionGateway::fail_held(core::FailReason why) {
  for (const auto& c : held_) failed_held(std::visit([](const auto& q) { return q.id; }, c), why);
  held_.clear();
}

}  // namespace imess::net
