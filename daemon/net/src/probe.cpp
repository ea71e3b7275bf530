// The Probe cycle on the io thread: two planned lines with the Probe's id (the approach at the
// move feed up to PrehitDist before the target, the search at ProbeSpeed up to SearchDist
// beyond it), and the commands queued after a Probe, held unplanned until its Done gives the
// place the cycle ended (the retract from the hit, known only after the hit).
#include <spdlog/spdlog.h>

#include "imess/net/server.hpp"
#include "imess/planner/probe.hpp"
#include "imess/net/wording.hpp"

namespace imess::net {

planner::AppendResult Server::plan_probe(const protocol::Probe& c) {
  const planner::Pose start = planner_.position();
  planner::Pose target = start;
  if (c.words.x) target[0] = *c.words.x;
  if (c.words.y) target[1] = *c.words.y;
  if (c.words.z) target[2] = *c.words.z;
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

// Before the start is known: the axes the command names lie within the travel.
planner::AppendResult Server::check_held(const QueuedCommand& c) const {
  const protocol::PathWords* w = nullptr;
  std::uint32_t id = 0;
  if (const auto* m = std::get_if<protocol::MoveTo>(&c)) w = &m->words, id = m->id;
  if (const auto* a = std::get_if<protocol::ArcTo>(&c)) w = &a->words, id = a->id;
  if (const auto* p = std::get_if<protocol::Probe>(&c)) w = &p->words, id = p->id;
  if (!w) return {planner::PlanError::None, 0};
  const auto& m = planner_.machine();
  const std::optional<double> named[3] = {w->x, w->y, w->z};
  for (int a = 0; a < 3 && a < m.count; ++a)
    if (named[a] && (*named[a] < m.axes[a].travel_min || *named[a] > m.axes[a].travel_max))
      return {planner::PlanError::OutOfTravel, id, static_cast<std::int8_t>(a), *named[a]};
  return {planner::PlanError::None, id};
}

// The Probe ended at `from`: what waited is planned from there, up to the next Probe (which
// holds the rest again). One the planner refuses now fails with the planner's reason.
void Server::plan_held(const core::Vec3& from) {
  if (held_.empty()) return;
  planner::Pose here{};
  for (int a = 0; a < core::kAxes; ++a) here[a] = from[a];
  planner_.set_position(here);
  planning_ = true;
  while (!held_.empty() && !probe_open_) {
    const QueuedCommand c = held_.front();
    held_.pop_front();
    auto res = plan(c);
    if (!res.ok()) {
      const bool travel = res.error == planner::PlanError::OutOfTravel;
      log_limited(spdlog::level::warn, "held-refused", planner::describe(res, planner_.machine()));
      broadcast(failed_line(res.id, travel ? core::FailReason::OutOfTravel : core::FailReason::Refused));
    }
  }
  if (unsent_.empty() && in_loop_.empty() && planner_.pending() == 0 && planner_.ready() == 0) planning_ = false;
}

void Server::fail_held(core::FailReason why) {
  for (const auto& c : held_) broadcast(failed_line(std::visit([](const auto& q) { return q.id; }, c), why));
  held_.clear();
}

}  // namespace imess::net
