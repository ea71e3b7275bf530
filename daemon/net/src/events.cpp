// Motion-loop events -> replies and broadcasts; periodic debug logs.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include "imess/net/server.hpp"
#include "imess/net/wording.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

using core::EventKind;

void Server::wait_for_events() {
  wake_wait_->async_wait(boost::asio::posix::stream_descriptor::wait_read, [this](boost::system::error_code ec) {
    if (ec || !running_) return;
    wake_->drain();  // before the drain: a notify after this point wakes us again
    ++woken_;
    pump_events();
    wait_for_events();
  });
}

void Server::backstop_events() {
  if (core_.events().read_available() > 0) ++backstop_found_;  // a wake-up was missed (or none is wired)
  pump_events();
}

void Server::pump_events() {
  core::Event e;
  while (core_.events().pop(e)) {
    switch (e.kind) {
      case EventKind::Reply: {
        if (e.client == IppServer::kClientId) {  // the I++ session's Home
          to_ipp("CoreReply", [&] { ipp_->core_reply(e); });
          break;
        }
        auto it = sessions_.find(e.client);
        if (it == sessions_.end()) break;  // the client left before the answer (or 0: stop_machine)
        if (it->second->info().in_flight > 0) --it->second->info().in_flight;
        if (e.refusal == core::Refusal::None) {
          reply(*it->second, e.seq, protocol::format_ok(command_verb(e.command)));
        } else {
          auto w = refusal_wording(e.refusal);
          reply(*it->second, e.seq, protocol::format_err(w.code, std::string(w.text)));
        }
        break;
      }
      case EventKind::MeasPt: {
        ++points_;
        core::Event point = e;  // the probe offset (a qualification's) moves every measured point
        point.p += hal::Vec3(config_.probe_offset[0], config_.probe_offset[1], config_.probe_offset[2]);
        send_hit(point);  // journal, then Hit, then the 1996 MeasPt
        to_ipp("Hit", [&] { ipp_->hit(point); });
        if (config_.log_motion)
          spdlog::info("point {}: {:.4f} {:.4f} {:.4f} {} dir {:.4f} {:.4f} {:.4f}", points_, point.p.x(), point.p.y(), point.p.z(),
                       e.compensated ? "compensated" : "as is (ForcePt)", e.dir.x(), e.dir.y(), e.dir.z());
        else
          spdlog::info("point {}: {:.3f} {:.3f} {:.3f}", points_, point.p.x(), point.p.y(), point.p.z());
        if (config_.beep && isatty(STDERR_FILENO)) {
          [[maybe_unused]] auto n = ::write(STDERR_FILENO, "\a", 1);
        }
        break;
      }
      case EventKind::State:
        broadcast(protocol::format_event("State", mode_name(e.mode)));
        if (config_.log_motion) spdlog::info("state {}", mode_name(e.mode));
        to_ipp("Retry", [&] { ipp_->retry(); });  // a move of the I++ session waiting for the machine to stand
        break;
      case EventKind::Limit: {
        std::string text = std::string(1, layout().letters[e.axis]) + (e.side < 0 ? " neg" : " pos");
        broadcast(protocol::format_event("Limit", text));
        spdlog::warn("limit switch {}", text);
        break;
      }
      case EventKind::Warn: {
        auto w = warning_wording(e.warning);
        const std::string_view text = e.reason ? std::string_view(e.reason) : w.text;  // the loop's own why, when it says one
        broadcast(protocol::format_event("Warn", std::string(w.name) + " " + std::string(text)));
        spdlog::warn("{}: {} (at {:.3f} {:.3f} {:.3f})", w.name, text, e.p.x(), e.p.y(), e.p.z());
        if (e.warning == core::Warning::HomingFailed) to_ipp("HomeFailed", [&] { ipp_->home_failed(); });
        break;
      }
      case EventKind::Fault: {
        auto w = fault_wording(e.fault);
        broadcast(protocol::format_event("Fault", std::string(w.name) + " " + std::string(w.text)));
        spdlog::error("fault {}: {}", w.name, w.text);
        to_ipp("HomeFailed", [&] { ipp_->home_failed(); });
        break;
      }
      case EventKind::Homed:
        broadcast(protocol::format_event("Homed", ""));
        spdlog::info("reference search done: machine homed");
        to_ipp("Homed", [&] { ipp_->homed(); });
        break;
      case EventKind::Done:
      case EventKind::Failed: on_segment_end(e); break;
      case EventKind::QueueDropped:  // a limit, fault or hit: what the loop never received fails too
        drops_ = e.id;
        drop_planned(e.fail);
        break;
      case EventKind::QueueLow:  // the loop holds only the segment it runs: end the plan at rest
        planner_.flush();
        feed_segments();
        break;
    }
  }
  const std::uint64_t departures = core_.snapshot().rest_departures;
  if (departures != rest_departures_seen_) {  // the position left a rest: show it at once
    rest_departures_seen_ = departures;
    watch_start_of_motion();
  } else if (start_watch_until_) {  // the loop wakes us each cycle after a departure: changed yet?
    report_start_of_motion();
  }
}

void Server::log_periodic() {
  const auto& snap = core_.snapshot();
  if (config_.log_status)
    spdlog::info("status X {:#07x} Y {:#07x} Z {:#07x} inputs {:#04x} {:#04x} {:#04x} hw errors {} events dropped {}",
                 snap.status[0], snap.status[1], snap.status[2], snap.inputs[0], snap.inputs[1], snap.inputs[2],
                 snap.hardware_errors, snap.events_dropped);
  if (config_.log_timing) spdlog::info("loop: {}", stats_line());
  if (config_.log_timing)
    spdlog::info("io: {} wake-ups, {} times the {:g} ms backstop found events first", woken_, backstop_found_,
                 config_.event_backstop_ms);
}

}  // namespace imess::net
