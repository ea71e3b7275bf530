// Queued moves on the io thread: MoveTo / ArcTo / Dwell / SetOut become planner requests, final
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

std::uint32_t id_of(const QueuedCommand& c) {
  return std::visit([](const auto& q) { return q.id; }, c);
}

std::string_view verb_of(const QueuedCommand& c) {
  static constexpr std::string_view kVerbs[] = {"MoveTo", "ArcTo", "Dwell", "Probe", "SetOut"};
  return kVerbs[c.index()];
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

bool Server::plan_from_here(std::string& why) {
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

// One queued command: Ok when planned (or held behind a running Probe), Err when refused.
void Server::queue_command(Session& s, std::uint32_t slot, const QueuedCommand& c) {
  const std::string_view verb = verb_of(c);
  if (const auto* w = words_of(c); w && !axes_known(s, slot, *w)) return;  // a letter the machine lacks
  if (const auto* o = std::get_if<protocol::SetOut>(&c); o && !find_output(o->output)) {
    reply(s, slot, format_err(ErrorCode::BadValue, "SetOut " + std::to_string(o->id) + ": no output '" + o->output +
                                                       "'; this machine has " + output_names()));
    return;
  }
  if (std::holds_alternative<protocol::ArcTo>(c) &&
      (layout().cartesian_axis(0) < 0 || layout().cartesian_axis(1) < 0 || layout().cartesian_axis(2) < 0)) {
    reply(s, slot, format_err(ErrorCode::BadValue, "ArcTo needs the linear axes X Y Z; this machine has " + layout().names()));
    return;
  }
  if (const auto* arc = std::get_if<protocol::ArcTo>(&c)) {  // words that make no arc, wherever it starts
    std::string bad;
    arc_shape(*arc, bad);
    if (!bad.empty()) {
      reply(s, slot, format_err(ErrorCode::BadValue, bad));
      return;
    }
  }
  if (probe_open_) {  // its start is the Probe's end: checked now as far as possible, planned then
    if (auto res = check_held(c); !res.ok()) {
      reply(s, slot, format_err(ErrorCode::OutOfTravel, planner::describe(res, planner_.machine())));
      return;
    }
    held_.push_back(c);
    if (config_.log_motion) spdlog::info("client {}: {} {} held until Probe {} is done", s.id(), verb, id_of(c), *probe_open_);
    reply(s, slot, format_ok(std::string(verb)));
    return;
  }
  std::string why;
  if (!plan_from_here(why)) {
    reply(s, slot, format_err(ErrorCode::Busy, why));
    return;
  }
  auto res = plan(c);
  if (!res.ok()) {
    const auto code = res.error == planner::PlanError::OutOfTravel ? ErrorCode::OutOfTravel : ErrorCode::BadValue;
    reply(s, slot, format_err(code, planner::describe(res, planner_.machine())));
    if (unsent_.empty() && in_loop_.empty()) planning_ = false;
    return;
  }
  if (config_.log_motion) spdlog::info("client {}: {} {} queued", s.id(), verb, id_of(c));
  reply(s, slot, format_ok(std::string(verb)));
  schedule_flush_check();
}

// The command's planner request(s) from where the planned path ends; its id into unsent_.
planner::AppendResult Server::plan(const QueuedCommand& c) {
  const planner::Pose start = planner_.position();
  const auto& p = core_.params();
  const double move_feed = p.goto_speed * p.speed_level;
  planner::AppendResult res;
  if (const auto* m = std::get_if<protocol::MoveTo>(&c)) {
    planner::Line l;
    l.id = m->id;
    l.target = target_of(m->words, start);
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
    a.target = target_of(w, start);
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
    const core::OutputSettings& out = *find_output(o->output);  // queue_command checked the name
    res = planner_.append(planner::SetOutput{o->id, static_cast<std::uint16_t>(out.number), o->on ? 1.0 : 0.0, out.settle_s});
  } else {
    res = plan_probe(std::get<protocol::Probe>(c));
    if (res.ok()) probe_open_ = res.id;
  }
  if (res.ok()) unsent_.push_back(id_of(c));
  return res;
}

const core::OutputSettings* Server::find_output(std::string_view name) const noexcept {
  return core::find_output(core_.config(), name);
}

std::string Server::output_names() const {
  const auto& cfg = core_.config();
  if (cfg.output_count == 0) return "no outputs";
  std::string names = "the outputs";
  for (int i = 0; i < cfg.output_count; ++i) names += (i ? ", " : " ") + std::string(cfg.outputs[i].name_view());
  return names;
}

// Outputs: every output by name with its state as last switched, then whether the probe is
// armed (powered and past its arming time).
void Server::outputs_status(Session& s, std::uint32_t slot) {
  const auto& cfg = core_.config();
  const auto& snap = core_.snapshot();
  std::string line;
  for (int i = 0; i < cfg.output_count; ++i)
    line += std::string(cfg.outputs[i].name_view()) + ((snap.outputs >> i) & 1u ? " on " : " off ");
  line += std::string("ProbeArmed ") + (snap.probe_armed ? "yes" : "no");
  reply(s, slot, format_ok("Outputs", line));
}

void Server::queue_status(Session& s, std::uint32_t slot) {
  const auto& snap = core_.snapshot();
  const std::size_t pending = unsent_.size() + in_loop_.size() + held_.size();
  reply(s, slot, format_ok("Queue", "Pending " + std::to_string(pending) + " Running " +
                                        (snap.path_running ? std::to_string(snap.path_id) : std::string("none")) +
                                        " Held " + (snap.path_held ? "yes" : "no")));
}

void Server::feed_segments() {
  planner::PlannedSegment seg;
  while (core_.segment_room() > 0 && planner_.take(seg)) {
    // A Probe's search whose approach has already been answered (it failed before the
    // search was fed): its id is closed, the search must never run. It is not sent.
    const bool search = seg.probe == planner::ProbePhase::Search;
    if (search && (in_loop_.empty() || in_loop_.back().first != seg.id) && (unsent_.empty() || unsent_.front() != seg.id))
      continue;
    if (!core_.submit_segment({seg, core_.stop_ticket(), drops_})) {
      // cannot happen (room was checked, one producer); never lose an id silently
      broadcast(failed_line(seg.id, core::FailReason::Faulted));
      if (!unsent_.empty()) unsent_.pop_front();
      continue;
    }
    // A Probe's search after its approach: the same id, one entry (its approach took it from unsent_).
    if (search && !in_loop_.empty() && in_loop_.back().first == seg.id) {
      in_loop_.back().second += seg.duration();
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
  if (IppServer::is_own_id(e.id)) {  // the I++ session's: it answers for them
    if (unsent_.empty() && in_loop_.empty() && planner_.pending() == 0 && planner_.ready() == 0) planning_ = false;
    to_ipp("SegmentEnd", [&] { ipp_->segment_end(e); });
    flush_check();
    return;
  }
  if (program_segment_end(e)) {  // a program's: Block and ProgEnd speak for it
    flush_check();
    return;
  }
  const bool probe_closed = probe_open_ && *probe_open_ == e.id && (e.kind == core::EventKind::Failed || e.probe_end);
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
  if (probe_closed) {
    probe_open_.reset();
    if (e.kind == core::EventKind::Done)
      plan_held(e.end);
    else
      fail_held(core::FailReason::Stopped);  // the cycle failed: what was to follow it never runs
  }
  flush_check();
}

void Server::drop_planned(core::FailReason why) {
  const bool program = program_.running() || program_.tail;  // its ids are not broadcast
  if (!program)
    for (auto id : unsent_)
      if (!IppServer::is_own_id(id)) broadcast(failed_line(id, why));
  unsent_.clear();
  probe_open_.reset();
  fail_held(why);
  planner::Pose here{};
  planner_.set_position(here);  // discards what was not taken; the next queue starts anew
  planning_ = false;
  to_ipp("Dropped", [&] { ipp_->dropped(why); });
  // A limit, a fault or an unexpected touch dropped the loop's queue: the program failed
  // (a stop ends it as aborted, in stop_machine).
  if (program_.running() && why != core::FailReason::Stopped) {
    const std::size_t block = std::max(program_.shown_block, program_.done_block + 1);
    const int line = block >= 1 && block <= program_.items.size() ? program_.items[block - 1].line : 0;
    end_program(ProgramOutcome::Failed, line, "Failed " + std::string(fail_wording(why).name));
  }
}

}  // namespace imess::net
