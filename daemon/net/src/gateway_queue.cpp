// The gateway's queued moves: MoveTo / ArcTo / Dwell / SetOut (and every front end's planner
// requests) become planned segments, final segments go into the motion loop's segment ring,
// Done / Failed come back as events to the id's owner.
// Flush rule: the planner's tail is made final (ending at rest) when the loop holds less than
// kFlushLead of motion — checked after the lines that arrived together, on every Done and
// Failed, and at once when the loop reports QueueLow — so moves sent in one burst are linked
// by look-ahead, and a lone move starts without waiting for a timer.
#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "imess/net/motion_gateway.hpp"
#include "imess/net/wording.hpp"

namespace imess::net {

namespace {
constexpr double kFlushLead = 0.05;  // s of motion the loop should hold before the plan must end at rest

std::uint32_t id_of(const QueuedCommand& c) {
  return std::visit([](const auto& q) { return q.id; }, c);
}

// A number as a person typed it: 2.5, 0, 1e+06.
std::string as_typed(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// An arc's plane and turns from its words: N when given (any orientation; a planar arc, as
// DirectCMM's MoveInArc), else by the offsets named: I J or neither XY, I K ZX, J K YZ
// (G17 / G18 / G19), where the third axis makes a helix. P is LinuxCNC's: the number of
// turns, P1 the arc alone. Empty why: the words make an arc.
struct ArcShape {
  std::array<double, 3> normal{0, 0, 1};
  int extra_turns = 0;
};

ArcShape arc_shape(const protocol::ArcTo& c, std::string& why) {
  const auto& w = c.words;
  ArcShape shape;
  const std::string name = "ArcTo " + std::to_string(c.id) + ": ";
  if (w.n) {
    shape.normal = *w.n;
  } else if (w.k && w.i && w.j) {
    why = name + "I J K together need N i j k, the plane's normal; I J is the XY plane, I K the ZX plane, J K the YZ plane";
  } else if (w.k && !w.i && !w.j) {
    why = name + "K alone names no plane; give I K (ZX plane) or J K (YZ plane), with I0 or J0 if need be, or N i j k";
  } else if (w.k) {
    shape.normal = w.i ? std::array<double, 3>{0, 1, 0} : std::array<double, 3>{1, 0, 0};
  }
  if (w.p) {
    if (!(*w.p >= 1 && *w.p <= protocol::kMaxArcTurns && *w.p == std::floor(*w.p)))
      why = name + "P is the number of turns, a whole number from 1 (the arc alone) to " +
            std::to_string(protocol::kMaxArcTurns) + ", got " + as_typed(*w.p);
    else
      shape.extra_turns = static_cast<int>(*w.p) - 1;
  }
  return shape;
}
}  // namespace

std::string arc_refusal(const protocol::ArcTo& c) {
  std::string why;
  arc_shape(c, why);
  return why;
}

bool MotionGateway::plan_from_here(std::string& why) {
  if (planning_) return true;
  const auto& snap = core_.snapshot();
  if ((snap.mode != core::Mode::Idle && snap.mode != core::Mode::Free) || !in_loop_.empty()) {
    why = std::string("the machine is busy (State ") + std::string(mode_name(snap.mode)) +
          "); queue moves when it stands, or StopMv";
    return false;
  }
  planner_.set_position(pose_of(snap.position));
  planning_ = true;
  return true;
}

planner::AppendResult MotionGateway::queue(const QueuedCommand& c) {
  auto res = plan(c);
  if (!res.ok() && unsent_.empty() && in_loop_.empty()) planning_ = false;
  return res;
}

planner::AppendResult MotionGateway::append(const planner::Request& r) {
  planning_ = true;
  const auto res = planner_.append(r);
  const std::uint32_t id = std::visit([](const auto& q) { return q.id; }, r);
  if (res.ok() && (unsent_.empty() || unsent_.back() != id)) unsent_.push_back(id);
  return res;
}

void MotionGateway::start_at(const planner::Pose& pose) { planner_.set_position(pose); }

void MotionGateway::end_plan_if_idle() {
  if (unsent_.empty() && in_loop_.empty() && planner_.pending() == 0 && planner_.ready() == 0) planning_ = false;
}

void MotionGateway::flush_and_feed() {
  planner_.flush();
  feed_segments();
}

std::optional<std::uint32_t> MotionGateway::first_in_loop() const noexcept {
  if (in_loop_.empty()) return std::nullopt;
  return in_loop_.front().first;
}

bool MotionGateway::in_loop_between(std::uint32_t first, std::uint32_t last) const noexcept {
  for (const auto& [id, seconds] : in_loop_)
    if (id >= first && id <= last) return true;
  return false;
}

// The command's planner request(s) from where the planned path ends; its id into unsent_.
planner::AppendResult MotionGateway::plan(const QueuedCommand& c) {
  const planner::Pose start = planner_.position();
  const auto& p = core_.params();
  const double move_feed = p.goto_speed * p.speed_level;
  planner::AppendResult res;
  if (const auto* m = std::get_if<protocol::MoveTo>(&c)) {
    planner::Line l;
    l.id = m->id;
    l.target = target_of(layout(), m->words, start);
    // F: the feed rule of the planner (axes.hpp): mm/s along X Y Z, else U V W, else deg/s.
    l.feed = m->words.f.value_or(move_feed);
    res = planner_.append(l);
  } else if (const auto* c_arc = std::get_if<protocol::ArcTo>(&c)) {
    // ArcTo id CW|CCW X Y Z I J K [N i j k] [P] [F]: the end (unnamed axes keep their
    // position), the centre at start + (I, J, K) (a missing one is 0); the plane and turns
    // as arc_shape says (queue_command refused words that make no arc).
    const auto& w = c_arc->words;
    std::string unused;
    const ArcShape shape = arc_shape(*c_arc, unused);
    // In the machine's X Y Z axes (queue_command refused an ArcTo on a machine without them).
    const int ix = layout().cartesian_axis(0), iy = layout().cartesian_axis(1), iz = layout().cartesian_axis(2);
    planner::Arc a;
    a.id = c_arc->id;
    a.target = target_of(layout(), w, start);
    a.centre = {start[ix] + w.i.value_or(0), start[iy] + w.j.value_or(0), start[iz] + w.k.value_or(0)};
    a.normal = shape.normal;
    a.planar = w.n.has_value();
    a.plane_axes = {static_cast<std::int8_t>(ix), static_cast<std::int8_t>(iy), static_cast<std::int8_t>(iz)};
    a.ccw = c_arc->ccw;
    a.turns = shape.extra_turns;
    a.feed = w.f.value_or(move_feed);
    res = planner_.append(a);
  } else if (const auto* d = std::get_if<protocol::Dwell>(&c)) {
    res = planner_.append(planner::Dwell{d->id, d->seconds});
  } else if (const auto* o = std::get_if<protocol::SetOut>(&c)) {
    const core::OutputSettings& out = *core::find_output(core_.config(), o->output);  // queue_command checked the name
    res = planner_.append(planner::SetOutput{o->id, static_cast<std::uint16_t>(out.number), o->on ? 1.0 : 0.0, out.settle_s});
  } else if (const auto* sl = std::get_if<protocol::ScanLine>(&c)) {
    res = plan_scan(sl->id, scan_shape(*sl), scan_settings(sl->speed));
  } else if (const auto* sc = std::get_if<protocol::ScanCircle>(&c)) {
    res = plan_scan(sc->id, scan_shape(*sc), scan_settings(sc->speed));
  } else {
    res = plan_probe(std::get<protocol::Probe>(c));
    if (res.ok()) probe_open_ = res.id;
  }
  if (res.ok()) unsent_.push_back(id_of(c));
  return res;
}

void MotionGateway::feed_segments() {
  planner::PlannedSegment seg;
  while (core_.segment_room() > 0 && planner_.take(seg)) {
    // A Probe's search whose approach has already been answered (it failed before the
    // search was fed): its id is closed, the search must never run. It is not sent. The same
    // for a scan's segments after its first (Position).
    const bool search = seg.probe == planner::ProbePhase::Search ||
                        (seg.scan.phase != planner::ScanPhase::None && seg.scan.phase != planner::ScanPhase::Position);
    if (search && (in_loop_.empty() || in_loop_.back().first != seg.id) && (unsent_.empty() || unsent_.front() != seg.id))
      continue;
    if (!core_.submit_segment({seg, core_.stop_ticket(), drops_})) {
      // cannot happen (room was checked, one producer); never lose an id silently
      failed_unsent(seg.id, core::FailReason::Faulted);
      if (!unsent_.empty()) unsent_.pop_front();
      continue;
    }
    // A Probe's search after its approach, a scan's segment after its first: the same id, one
    // entry (the first took it from unsent_).
    if (search && !in_loop_.empty() && in_loop_.back().first == seg.id) {
      in_loop_.back().second += seg.duration();
      continue;
    }
    if (!unsent_.empty()) unsent_.pop_front();
    in_loop_.emplace_back(seg.id, seg.duration());
  }
}

void MotionGateway::schedule_flush_check() {
  if (flush_check_posted_) return;
  flush_check_posted_ = true;
  boost::asio::post(io_, [this] {
    flush_check_posted_ = false;
    flush_check();
  });
}

void MotionGateway::flush_check() {
  if (planner_.pending() > 0) {
    double lead = planner_.ready_duration();
    for (const auto& [id, seconds] : in_loop_) lead += seconds;
    if (lead < kFlushLead) planner_.flush();
  }
  feed_segments();
}

// The Done / Failed goes to the id's owner: a front end's own ids (the I++ DME session's, a
// program's) to it alone; the rest are MESSD's queued moves (the fallback), after whose
// answer the plan may end and a closed Probe releases what it held.
void MotionGateway::on_segment_end(const core::Event& e) {
  auto it = std::find_if(in_loop_.begin(), in_loop_.end(), [&](const auto& x) { return x.first == e.id; });
  if (it != in_loop_.end()) in_loop_.erase(it);
  MotionObserver* owner = observers_.owner_of(e.id);
  if (owner && owner != observers_.fallback()) {
    owner->guarded("SegmentEnd", [&] { owner->segment_end(e); });
    fail_deferred();
    flush_check();
    return;
  }
  const bool probe_closed = probe_open_ && *probe_open_ == e.id && (e.kind == core::EventKind::Failed || e.probe_end);
  if (owner) owner->guarded("SegmentEnd", [&] { owner->segment_end(e); });
  fail_deferred();  // the ids queued behind this one, failed by a stop: after it, in queue order
  end_plan_if_idle();  // the queue ran out: the next one starts where the machine stands
  if (probe_closed) {
    probe_open_.reset();
    if (e.kind == core::EventKind::Done)
      plan_held(e.end);
    else
      fail_held(core::FailReason::Stopped);  // the cycle failed: what was to follow it never runs
  }
  flush_check();
}

// Held commands are MESSD's queued moves (the fallback's), whatever their id.
void MotionGateway::failed_held(std::uint32_t id, core::FailReason why) {
  if (MotionObserver* o = observers_.fallback()) {
    if (defer_failure(id, why)) return;
    o->guarded("Failed", [&] { o->unsent_failed(id, why); });
  }
}

void MotionGateway::failed_unsent(std::uint32_t id, core::FailReason why) {
  MotionObserver* owner = observers_.owner_of(id);
  if (!owner) return;
  if (owner == observers_.fallback() && defer_failure(id, why)) return;
  owner->guarded("Failed", [&] { owner->unsent_failed(id, why); });
}

// A MESSD client reads its Failed lines in queue order: the ids the loop holds fail there (their
// events arrive a cycle later), so the ids queued behind them, which fail here, wait for those.
bool MotionGateway::defer_failure(std::uint32_t id, core::FailReason why) {
  if (in_loop_.empty() && deferred_.empty()) return false;
  if (deferred_.empty()) {
    deferred_until_.clear();
    for (const auto& [loop_id, seconds] : in_loop_) deferred_until_.push_back(loop_id);
  }
  deferred_.emplace_back(id, why);
  return true;
}

void MotionGateway::fail_deferred() {
  if (deferred_.empty()) return;
  for (auto id : deferred_until_)
    if (std::any_of(in_loop_.begin(), in_loop_.end(), [&](const auto& x) { return x.first == id; })) return;
  const auto fails = std::move(deferred_);
  deferred_.clear();
  deferred_until_.clear();
  MotionObserver* o = observers_.fallback();
  for (const auto& f : fails)  // not a structured binding: clang 14 (the fuzz build) cannot capture one
    if (o) o->guarded("Failed", [&] { o->unsent_failed(f.first, f.second); });
}

void MotionGateway::drop_planned(core::FailReason why) {
  for (auto id : unsent_) failed_unsent(id, why);  // each owner answers for its own (a program's are not broadcast)
  unsent_.clear();
  probe_open_.reset();
  fail_held(why);
  planner::Pose here{};
  planner_.set_position(here);  // discards what was not taken; the next queue starts anew
  planning_ = false;
  observers_.each("Dropped", [&](MotionObserver& o) { o.dropped(why); });
}

// The stop lane (read first in every motion cycle); the queued moves the loop has not
// received fail here, those it has fail there (their ids were stamped before this stop).
void MotionGateway::stop(std::string_view who) {
  abandon_plan();
  observers_.each("Stopped", [&](MotionObserver& o) { o.stopped(who); });
}

void MotionGateway::abandon_plan() {
  core_.request_stop();
  drop_planned(core::FailReason::Stopped);
}

}  // namespace imess::net
