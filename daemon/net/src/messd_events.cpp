// Motion-loop events -> MESSD replies and broadcasts.
#include "imess/net/messd_events.hpp"

#include <spdlog/spdlog.h>

#include <Eigen/Geometry>

#include "imess/net/wording.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"

namespace imess::net {

using Vec = Eigen::Vector3d;

bool MessdEvents::core_reply(const core::Event& e) {
  Session* s = sessions_.find(e.client);
  if (!s) return false;  // the client left before the answer (or 0: a stop), or not a MESSD client's
  if (s->info().in_flight > 0) --s->info().in_flight;
  if (e.refusal == core::Refusal::None) {
    sessions_.reply(*s, e.seq, protocol::format_ok(command_verb(e.command)));
  } else {
    auto w = refusal_wording(e.refusal);
    sessions_.reply(*s, e.seq, protocol::format_err(w.code, std::string(w.text)));
  }
  return true;
}

// Journaled first (HitService): Hit, then the 1996 MeasPt, then PartPt.
void MessdEvents::hit(const core::Event&, const JournaledHit& h) {
  sessions_.broadcast(h.line);
  sessions_.broadcast(protocol::format_meas_pt(h.msg.p));
  send_part_point(h.msg);
}

void MessdEvents::scanned(const core::Event&, const JournaledHit& h) { sessions_.broadcast(h.line); }

void MessdEvents::state(core::Mode mode) {
  sessions_.broadcast(protocol::format_event("State", mode_name(mode)));
  if (log_motion_) spdlog::info("state {}", mode_name(mode));
}

void MessdEvents::limit(const core::Event& e) {
  std::string text = std::string(1, gateway_.layout().letters[e.axis]) + (e.side < 0 ? " neg" : " pos");
  sessions_.broadcast(protocol::format_event("Limit", text));
  spdlog::warn("limit switch {}", text);
}

void MessdEvents::warning(const core::Event& e) {
  auto w = warning_wording(e.warning);
  const std::string_view text = e.reason ? std::string_view(e.reason) : w.text;  // the loop's own why, when it says one
  // HostStall carries how long the loop stalled: "Warn HostStall 35 ms stall beyond ..."
  const std::string value = e.warning == core::Warning::HostStall ? std::to_string(e.value) + " " : "";
  sessions_.broadcast(protocol::format_event("Warn", std::string(w.name) + " " + value + std::string(text)));
  spdlog::warn("{}: {} (at {:.3f} {:.3f} {:.3f})", w.name, text, e.p.x(), e.p.y(), e.p.z());
}

void MessdEvents::fault(const core::Event& e) {
  auto w = fault_wording(e.fault);
  sessions_.broadcast(protocol::format_event("Fault", std::string(w.name) + " " + std::string(w.text)));
  spdlog::error("fault {}: {}", w.name, w.text);
}

void MessdEvents::homed() {
  sessions_.broadcast(protocol::format_event("Homed", ""));
  spdlog::info("reference search done: machine homed");
}

// Done / Failed of a queued move of a MESSD client.
void MessdEvents::segment_end(const core::Event& e) {
  if (e.kind == core::EventKind::Done) {
    sessions_.broadcast(protocol::format_event("Done", std::to_string(e.id)));
    if (log_motion_) spdlog::info("move {} done", e.id);
  } else {
    sessions_.broadcast(failed_line(e.id, e.fail));
    log_limited(log_, spdlog::level::warn, "move-failed", "move " + std::to_string(e.id) + " failed: " +
                                                              std::string(fail_wording(e.fail).name));
  }
}

void MessdEvents::unsent_failed(std::uint32_t id, core::FailReason why) { sessions_.broadcast(failed_line(id, why)); }

void MessdEvents::frame_changed(const std::string& active) { sessions_.broadcast(protocol::format_event("Frame", active)); }

void MessdEvents::control_changed(const std::optional<Controller>& owner) { sessions_.broadcast(control_event(owner)); }

void MessdEvents::control_taken(const Controller& was, const Controller& by) {
  if (Session* s = sessions_.find(was.session)) sessions_.send(*s, control_taken_warning(by));
}


// After a hit's Hit and MeasPt: the same point in the active part frame.
void MessdEvents::send_part_point(const protocol::HitMsg& hit) {
  if (frames_.active() == kMachineFrame) return;
  const auto& f = frames_.active_frame();
  const Vec p = f.point_from_parent(Vec(hit.p.x, hit.p.y, hit.p.z));
  const Vec d = f.direction_from_parent(Vec(hit.dir.x, hit.dir.y, hit.dir.z));
  std::string line = "PartPt " + std::to_string(hit.seq) + ' ' + frames_.active();
  for (int c = 0; c < 3; ++c) {
    line += ' ';
    protocol::append_fixed(line, p[c], 4);
  }
  for (int c = 0; c < 3; ++c) {
    line += ' ';
    protocol::append_fixed(line, d[c], 6);
  }
  line += '\n';
  sessions_.broadcast(line);
}

}  // namespace imess::net
