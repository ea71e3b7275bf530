// Is the client still there? The owner's dead-man (Watch), writers that stopped reading,
// controllers that fell silent, connections that never command. Rules in docs/protocol.md,
// "Control" and "Connections and idle clients".
#include <spdlog/spdlog.h>

#include "imess/net/liveness.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

using Clock = Session::Clock;

namespace {
std::chrono::duration<double> seconds(double s) { return std::chrono::duration<double>(s); }

std::string lost_reply_line(double timeout_s) {
  return protocol::format_err(protocol::ErrorCode::Internal,
                              "no answer from the motion loop within " + fmt::format("{:g}", timeout_s) +
                                  " s (its event queue overflowed); the command's effect is unknown, ask Status");
}

bool moving(core::Mode m) {
  return m == core::Mode::Jog || m == core::Mode::Move || m == core::Mode::Retract || m == core::Mode::Home;
}
}  // namespace

std::optional<Clock::time_point> Liveness::watch_deadline() const {
  const auto& owner = control_.owner();
  if (!owner) return std::nullopt;
  const Session* found = sessions_.find(owner->session);
  if (!found) return std::nullopt;
  const Session& s = *found;
  const auto& info = s.info();
  if (info.watch_ms <= 0) return std::nullopt;
  const auto ms = std::chrono::milliseconds(info.watch_ms);
  // Fired for this silence: look again one period on; bytes arriving meanwhile give a later
  // deadline than that, so none is missed.
  if (info.watch_fired_for == s.last_received()) return Clock::now() + ms;
  return s.last_received() + ms;
}

void Liveness::arm_housekeeping() {
  if (!running_) return;
  std::optional<Clock::time_point> next;
  auto earliest = [&](std::optional<Clock::time_point> t) {
    if (t && (!next || *t < *next)) next = t;
  };
  earliest(watch_deadline());
  earliest(journal_.sync_due());
  if (!next || (housekeeping_at_ && *housekeeping_at_ <= *next)) return;  // nothing waits, or armed earlier
  housekeeping_at_ = next;
  housekeeping_timer_.expires_at(*next);  // cancels a later wait, whose handler then does nothing
  housekeeping_timer_.async_wait([this](boost::system::error_code ec) {
    if (ec || !running_) return;
    housekeeping();
  });
}

void Liveness::housekeeping() {
  housekeeping_at_.reset();
  check_watch();
  journal_.sync_if_due();
  arm_housekeeping();
}

void Liveness::check_watch() {
  const auto& owner = control_.owner();
  if (!owner) return;
  Session* found = sessions_.find(owner->session);
  if (!found) return;
  Session& s = *found;
  auto& info = s.info();
  if (info.watch_ms <= 0 || info.watch_fired_for == s.last_received()) return;  // off, or fired for this silence
  if (Clock::now() - s.last_received() < std::chrono::milliseconds(info.watch_ms)) return;
  info.watch_fired_for = s.last_received();  // once per silence; the next bytes re-arm it
  const bool was_moving = moving(gateway_.snapshot().mode) || info.in_flight > 0;
  gateway_.stop("Watch");
  if (!was_moving) return;
  log_limited(log_, spdlog::level::warn, "watch",
              "client " + std::to_string(s.id()) + " silent for " + std::to_string(info.watch_ms) + " ms (Watch): machine stopped");
  sessions_.send(s, protocol::format_event("Warn", "WatchExpired silent for " + std::to_string(info.watch_ms) +
                                             " ms: the machine was stopped"));
}

void Liveness::check_clients() {
  const auto now = Clock::now();
  for (const auto& [name, count] : log_.take_expired(now))
    spdlog::warn("... suppressed {} similar '{}' lines", count, name);
  const auto& rules = config_.control;
  const auto reply_timeout = std::chrono::duration_cast<Clock::duration>(seconds(config_.reply_timeout_s));
  auto sessions = sessions_.all();  // drops erase from sessions_
  for (auto& [id, s] : sessions) {
    if (!s->open()) continue;
    // An answer from the motion loop that never came (its event ring overflowed) must not
    // hold back every later reply: the slot is answered Err 500 and the rest flow.
    if (auto lost = s->expire_replies(now, reply_timeout, lost_reply_line(config_.reply_timeout_s))) {
      auto& in_flight = s->info().in_flight;
      in_flight -= std::min<std::uint32_t>(in_flight, static_cast<std::uint32_t>(lost));
      log_limited(log_, spdlog::level::warn, "reply-lost",
                  "client " + std::to_string(id) + ": " + std::to_string(lost) + " replies not answered within " +
                      fmt::format("{:g}", config_.reply_timeout_s) + " s (events dropped: " +
                      std::to_string(gateway_.snapshot().events_dropped) + "); answered Err 500");
      if (!s->open()) continue;
    }
    // Output that does not drain: the client stopped reading (or was stopped, SIGSTOP, and
    // its receive buffer is full). No line would reach it any more: log and close.
    if (s->output_stalled_for(now) > seconds(rules.write_stall_s)) {
      s->close("dropped: its output has not drained for " + fmt::format("{:g}", rules.write_stall_s) +
               " s (not reading)");
      continue;
    }
    // Silence is normal for a monitor on an idle machine; it is not for a client that holds
    // control or asked for the dead-man (it promised keep-alives).
    const bool must_speak = control_.owns(id) || s->info().watch_ms > 0;
    if (must_speak && !s->dropping() && now - s->last_received() > seconds(rules.idle_drop_s))
      drop(*s, "nothing received for " + fmt::format("{:g}", rules.idle_drop_s) + " s while " +
                   (control_.owns(id) ? "holding control" : "Watch is on") +
                   "; connection closed (a blank line now and then keeps it open)");
    // A connection from a control host that never sends a command holds a slot — the reserved
    // ones too — for nothing: a hundred of them lock everyone out. Observer-only hosts are
    // capped by reserved_slots instead; a client that sent any command is never dropped here.
    const auto& info = s->info();
    if (rules.no_command_drop_s > 0 && info.may_control && !info.commanded && !s->dropping() &&
        now - info.connected_at > seconds(rules.no_command_drop_s))
      drop(*s, "no command within " + fmt::format("{:g}", rules.no_command_drop_s) +
                   " s of connecting; connection closed (send a command, e.g. Hello, to stay connected)");
  }
}

void Liveness::drop(Session& s, std::string_view why) {
  log_limited(log_, spdlog::level::warn, "drop-silent", "client " + std::to_string(s.id()) + " (" + s.peer() + "): " + std::string(why));
  control_.lose(s.id(), "dropped", true);
  s.drop(protocol::format_err(protocol::ErrorCode::Dropped, why));
}

Liveness::Liveness(boost::asio::io_context& io, const ServerConfig& config, SessionHub& sessions, ControlService& control,
                   MotionGateway& gateway, journal::Journal& journal, LogLimiter& log)
    : config_(config),
      sessions_(sessions),
      control_(control),
      gateway_(gateway),
      journal_(journal),
      log_(log),
      housekeeping_timer_(io),
      clients_timer_(io) {}

void Liveness::start() {
  running_ = true;
  const std::chrono::microseconds every(250000);
  clients_timer_.start(every, [every] { return every; }, [this] { check_clients(); });
}

void Liveness::stop() {
  running_ = false;
  housekeeping_timer_.cancel();
  clients_timer_.cancel();
}

}  // namespace imess::net
