// Queued moves on the MESSD wire: MoveTo / ArcTo / Dwell / Probe / SetOut checked against this
// machine and handed to the MotionGateway (Ok when planned or held behind a running Probe, Err
// when refused; Done / Failed follow as events), Queue and Outputs.
#include <spdlog/spdlog.h>

#include "imess/net/messd_dispatch.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

using protocol::ErrorCode;
using protocol::format_err;
using protocol::format_ok;

namespace {
std::uint32_t id_of(const QueuedCommand& c) {
  return std::visit([](const auto& q) { return q.id; }, c);
}

std::string_view verb_of(const QueuedCommand& c) {
  static constexpr std::string_view kVerbs[] = {"MoveTo", "ArcTo", "Dwell", "Probe", "SetOut", "ScanLine", "ScanCirc"};
  return kVerbs[c.index()];
}
}  // namespace

// One queued command: Ok when planned (or held behind a running Probe), Err when refused.
void MessdDispatch::queue_command(Session& s, std::uint32_t slot, const QueuedCommand& c) {
  const std::string_view verb = verb_of(c);
  if (const auto* w = words_of(c); w && !axes_known(s, slot, *w)) return;  // a letter the machine lacks
  if (const auto* o = std::get_if<protocol::SetOut>(&c); o && !core::find_output(gateway_.config(), o->output)) {
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
    const std::string bad = arc_refusal(*arc);
    if (!bad.empty()) {
      reply(s, slot, format_err(ErrorCode::BadValue, bad));
      return;
    }
  }
  if (std::holds_alternative<protocol::ScanLine>(c) || std::holds_alternative<protocol::ScanCircle>(c)) {
    // X Y Z as machine axes 0 1 2 (the scan's poses), and a shape that makes a scan.
    if (layout().cartesian_axis(0) != 0 || layout().cartesian_axis(1) != 1 || layout().cartesian_axis(2) != 2) {
      reply(s, slot, format_err(ErrorCode::BadValue, std::string(verb) + " needs the linear axes X Y Z; this machine has " + layout().names()));
      return;
    }
    const auto shape = std::holds_alternative<protocol::ScanLine>(c) ? scan_shape(std::get<protocol::ScanLine>(c))
                                                                     : scan_shape(std::get<protocol::ScanCircle>(c));
    const auto check = planner::scan_requests(id_of(c), gateway_.planned_end(), shape, gateway_.scan_settings());
    if (const auto* why = std::get_if<std::string>(&check)) {
      reply(s, slot, format_err(ErrorCode::BadValue, std::string(verb) + " " + std::to_string(id_of(c)) + ": " + *why));
      return;
    }
  }
  if (const auto probe = gateway_.open_probe()) {  // its start is the Probe's end: checked now as far as possible, planned then
    if (auto res = gateway_.hold(c); !res.ok()) {
      reply(s, slot, format_err(ErrorCode::OutOfTravel, planner::describe(res, gateway_.machine())));
      return;
    }
    if (config_.log_motion) spdlog::info("client {}: {} {} held until Probe {} is done", s.id(), verb, id_of(c), *probe);
    reply(s, slot, format_ok(std::string(verb)));
    return;
  }
  std::string why;
  if (!gateway_.plan_from_here(why)) {
    reply(s, slot, format_err(ErrorCode::Busy, why));
    return;
  }
  auto res = gateway_.queue(c);  // refused: a plan left empty ends
  if (!res.ok()) {
    const auto code = res.error == planner::PlanError::OutOfTravel ? ErrorCode::OutOfTravel : ErrorCode::BadValue;
    reply(s, slot, format_err(code, planner::describe(res, gateway_.machine())));
    return;
  }
  if (config_.log_motion) spdlog::info("client {}: {} {} queued", s.id(), verb, id_of(c));
  reply(s, slot, format_ok(std::string(verb)));
  gateway_.schedule_flush_check();
}

std::string MessdDispatch::output_names() const {
  const auto& cfg = gateway_.config();
  if (cfg.output_count == 0) return "no outputs";
  std::string names = "the outputs";
  for (int i = 0; i < cfg.output_count; ++i) names += (i ? ", " : " ") + std::string(cfg.outputs[i].name_view());
  return names;
}

// Outputs: every output by name with its state as last switched, then whether the probe is
// armed (powered and past its arming time).
void MessdDispatch::outputs_status(Session& s, std::uint32_t slot) {
  const auto& cfg = gateway_.config();
  const auto& snap = gateway_.snapshot();
  std::string line;
  for (int i = 0; i < cfg.output_count; ++i)
    line += std::string(cfg.outputs[i].name_view()) + ((snap.outputs >> i) & 1u ? " on " : " off ");
  line += std::string("ProbeArmed ") + (snap.probe_armed ? "yes" : "no");
  reply(s, slot, format_ok("Outputs", line));
}

void MessdDispatch::queue_status(Session& s, std::uint32_t slot) {
  const auto& snap = gateway_.snapshot();
  const std::size_t pending = gateway_.ids_pending();
  reply(s, slot, format_ok("Queue", "Pending " + std::to_string(pending) + " Running " +
                                        (snap.path_running ? std::to_string(snap.path_id) : std::string("none")) +
                                        " Held " + (snap.path_held ? "yes" : "no")));
}

}  // namespace imess::net
