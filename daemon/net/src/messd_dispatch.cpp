// MESSD client lines -> replies (answered here or by a service) or motion-loop commands (answered by the loop).
#include <spdlog/spdlog.h>

#include <cstdio>

#include "imess/net/params.hpp"
#include "imess/net/messd_dispatch.hpp"
#include "overloaded.hpp"
#include "imess/net/wording.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"
#include "imess/protocol/verbs.hpp"

namespace imess::net {

using protocol::ErrorCode;
using protocol::format_err;
using protocol::format_ok;

namespace {
std::string fixed(double v, int decimals = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}
}  // namespace

MessdDispatch::MessdDispatch(ServerConfig& config, MessdServices services)
    : config_(config),
      sessions_(services.sessions),
      gateway_(services.gateway),
      control_(services.control),
      hits_(services.hits),
      programs_(services.programs),
      frames_(services.frames),
      stream_(services.stream),
      stats_(services.stats),
      observers_(services.observers),
      log_(services.log) {}

void MessdDispatch::gone(Session& s) { control_.lose(s.id(), "disconnected", true); }

void MessdDispatch::on_line(Session& s, const protocol::FramedLine& line) {
  if (s.dropping()) return;
  if (config_.log_traffic) spdlog::info("[{}] > {}", s.id(), line.text);
  if (s.info().upload) {  // the lines of a program being uploaded, up to '.'
    // Except a stop: StopMv and Abort are no line of any program language, and the operator
    // typing a program into telnet must still be able to stop the machine from there.
    if (!line.overlong) {
      const auto parsed = protocol::parse_command(line.text);
      if (const auto* cmd = std::get_if<protocol::Command>(&parsed);
          cmd && (std::holds_alternative<protocol::StopMv>(*cmd) || std::holds_alternative<protocol::Abort>(*cmd))) {
        const std::uint32_t slot = s.reserve_reply();
        on_command(s, slot, *cmd);
        return;
      }
    }
    control_.heard(s.id());  // a program's lines: its owner is busy, not silent
    upload_line(s, line);
    return;
  }
  if (!line.overlong && protocol::is_blank(line.text)) return;  // no command: telnet users press Enter
  const std::uint32_t slot = s.reserve_reply();
  if (line.overlong) {
    reply(s, slot, format_err(ErrorCode::LineTooLong, "line longer than " + std::to_string(protocol::kMaxLineLength) +
                                                   " characters; it was discarded"));
    return;
  }
  auto parsed = protocol::parse_command(line.text);
  if (auto* err = std::get_if<protocol::ParseError>(&parsed)) {
    reply(s, slot, format_err(err->code, err->text));
    return;
  }
  on_command(s, slot, std::get<protocol::Command>(parsed));
}

bool MessdDispatch::to_core(Session& s, std::uint32_t slot, core::Command c) {
  c.client = s.id();
  c.seq = slot;
  if (config_.log_motion)
    spdlog::info("client {}: {} {:.3f} {:.3f} {:.3f}", s.id(), command_verb(c.kind), c.v[0], c.v[1], c.v[2]);
  // A client that floods gets QueueFull itself; its share of the ring stays bounded, so the
  // ring never fills up for anyone else.
  if (s.info().in_flight >= config_.control.max_in_flight) {
    const std::uint32_t n = config_.control.max_in_flight;
    reply(s, slot, format_err(ErrorCode::QueueFull, std::to_string(n) + (n == 1 ? " command" : " commands") +
                                                        " of this client " + (n == 1 ? "is" : "are") +
                                                        " waiting for the motion loop; retry when answered"));
    return false;
  }
  if (!gateway_.submit(c)) {
    log_limited(log_, spdlog::level::warn, "queue-full", "client " + std::to_string(s.id()) + ": the motion loop's command queue is full");
    reply(s, slot, format_err(ErrorCode::QueueFull, "the motion loop's command queue is full; retry"));
    return false;
  }
  ++s.info().in_flight;
  return true;
}

// StopMv from anyone, always accepted and answered at once: the stop lane takes no ring
// slot, so neither a crowd pressing stop nor a full ring can delay or refuse a stop.
void MessdDispatch::stop_request(Session& s, std::uint32_t slot) {
  gateway_.stop("StopMv");
  reply(s, slot, format_ok("StopMv"));
}

void MessdDispatch::on_command(Session& s, std::uint32_t slot, const protocol::Command& cmd) {
  using core::CommandKind;
  s.info().commanded = true;  // no longer a candidate for control.no_command_drop_s
  control_.heard(s.id());     // the owner's silence (control.handover_s) starts anew
  if (!allowed(s, cmd, slot)) return;
  // What would move the machine besides the program (its declaration says so): refused while one runs.
  if (protocol::moves_machine(cmd) && programs_.busy(protocol::verb_name(cmd), answer(s, slot))) return;
  // StartMv, GoTo, HandMv: x y z on the machine's X Y Z axes; GoTo leaves the others where they are.
  auto xyz_to_core = [&](CommandKind kind, const protocol::Xyz& p, double speed) {
    core::Command c{kind};
    if (!machine_vector(s, slot, p, c.v, c.axes)) return;
    c.speed = speed;
    to_core(s, slot, c);
  };
  std::visit(
      Overloaded{
          [&](const protocol::StartMv& c) { xyz_to_core(CommandKind::StartMv, c.percent, 0); },
          [&](const protocol::StopMv&) { stop_request(s, slot); },
          [&](const protocol::ForcePt&) { to_core(s, slot, {CommandKind::ForcePt}); },
          [&](const protocol::GoTo& c) { xyz_to_core(CommandKind::GoTo, c.target, c.speed.value_or(0)); },
          [&](const protocol::Home&) { to_core(s, slot, {CommandKind::Home}); },
          [&](const protocol::Free&) { to_core(s, slot, {CommandKind::Free}); },
          [&](const protocol::Reset&) { to_core(s, slot, {CommandKind::Reset}); },
          [&](const protocol::HandMv& c) { xyz_to_core(CommandKind::HandMv, c.delta, c.speed.value_or(0)); },
          [&](const protocol::Hello& c) { hello(s, slot, c); },
          [&](const protocol::Help&) { help(s, slot); },
          [&](const protocol::Status&) { reply(s, slot, format_ok("Status", status_line())); },
          [&](const protocol::Stats& c) { stats_.stats(s, slot, c); },
          [&](const protocol::Get& c) { get_param(s, slot, c); },
          [&](const protocol::Set& c) { set_param(s, slot, c); },
          [&](const protocol::Replay& c) { reply(s, slot, hits_.replay(s.id(), c.from)); },
          [&](const protocol::Quit&) {
            reply(s, slot, format_ok("Quit"));
            s.close_after_flush();
          },
          [&](const protocol::Take& c) { take(s, slot, c); },
          [&](const protocol::Release&) { release(s, slot); },
          [&](const protocol::Watch& c) {
            s.info().watch_ms = c.ms;
            s.info().watch_fired_for = {};
            reply(s, slot, format_ok("Watch"));
          },
          [&](const protocol::Version&) { reply(s, slot, format_ok("Version", config_.version)); },
          [&](const protocol::MoveTo& c) { queue_command(s, slot, c); },
          [&](const protocol::ArcTo& c) { queue_command(s, slot, c); },
          [&](const protocol::Dwell& c) { queue_command(s, slot, c); },
          [&](const protocol::Probe& c) { queue_command(s, slot, c); },
          [&](const protocol::SetOut& c) { queue_command(s, slot, c); },
          [&](const protocol::ScanLine& c) { queue_command(s, slot, c); },
          [&](const protocol::ScanCircle& c) { queue_command(s, slot, c); },
          [&](const protocol::Outputs&) { outputs_status(s, slot); },
          [&](const protocol::Queue&) { queue_status(s, slot); },
          [&](const protocol::Pause&) { to_core(s, slot, {CommandKind::Pause}); },
          [&](const protocol::Resume&) {
            programs_.resume();
            to_core(s, slot, {CommandKind::Resume});
          },
          [&](const protocol::JogAx& c) { jog_axes(s, slot, c); },
          [&](const protocol::Programs&) { programs_.list(answer(s, slot)); },
          [&](const protocol::Load& c) { programs_.load(s.id(), c.name, answer(s, slot)); },
          [&](const protocol::Upload& c) { begin_upload(s, slot, c.name); },
          [&](const protocol::Run& c) { programs_.run(s.id(), c.detached, answer(s, slot)); },
          [&](const protocol::Abort&) { abort_program(s, slot); },
          [&](const protocol::Program&) { programs_.status(answer(s, slot)); },
          [&](const protocol::Key& c) { press_key(s, slot, c.name); },
          [&](const protocol::Frames&) { frames_.list_frames(s, slot); },
          [&](const protocol::Frame& c) { frames_.show_frame(s, slot, c.name); },
          [&](const protocol::PartPos& c) { frames_.part_pos(s, slot, c.name); },
          [&](const protocol::UseFrame& c) { frames_.use_frame(s, slot, c.name); },
          [&](const protocol::SetFrame& c) { frames_.set_frame(s, slot, c); },
          [&](const protocol::Align& c) { frames_.align(s, slot, c); },
          [&](const protocol::DelFrame& c) { frames_.del_frame(s, slot, c.name); },
          [&](const protocol::Qualify& c) { qualify(s, slot, c); },
          [&](const protocol::Verdict& c) { verdict(s, slot, c); },
          [&](const protocol::Stream& c) { reply(s, slot, stream_.set_stream_rate(s, c.hz)); },
      },
      cmd);
}

// Key <name>: the operator's key for the I++ DME session that enabled the user (it arrives
// there as E0000 # KeyPress("name")); refused when no session listens for keys.
void MessdDispatch::press_key(Session& s, std::uint32_t slot, const std::string& name) {
  if (!observers_.any_listens_for_keys()) {
    reply(s, slot, format_err(ErrorCode::BadValue, "Key " + name + ": no I++ DME session has enabled the user; keys go to it only then"));
    return;
  }
  observers_.each("KeyPress", [&](MotionObserver& o) { o.key(name); });
  reply(s, slot, format_ok("Key"));
}

// Hello [name]: the client's name (the control event shows the owner under it), then the
// daemon's capabilities.
void MessdDispatch::hello(Session& s, std::uint32_t slot, const protocol::Hello& c) {
  if (!c.client.empty()) {
    log_limited(log_, spdlog::level::info, "hello", "client " + std::to_string(s.id()) + " is '" + c.client + "'");
    s.info().name = c.client;
    const bool owner = control_.owner() && control_.owner()->session == s.id();
    control_.rename(s.id(), controller_name(s.id(), c.client));
    if (owner) control_.announce();  // everyone sees the owner under its new name
  }
  const bool sim = gateway_.snapshot().simulated;
  reply(s, slot, format_ok("Hello", "IMESS 1 messd " + config_.version + " Caps jog goto home probe hand stats journal queue programs" +
                                 (sim ? " sim" : "")));
}

void MessdDispatch::help(Session& s, std::uint32_t slot) {
  std::string lines;
  for (const auto& v : protocol::verb_table())
    if (auto line = machine_help_line(v); !line.empty()) lines += line + "\n";
  reply(s, slot, lines + format_ok("Help"));
}

namespace {
std::string unknown_param(const std::string& name) {
  return format_err(ErrorCode::UnknownParameter, "no parameter '" + name + "'; Get alone lists them all");
}
}  // namespace

// Get [name]: one parameter, or all of them in one line.
void MessdDispatch::get_param(Session& s, std::uint32_t slot, const protocol::Get& c) {
  ParamPlaces at{gateway_, config_.report_hz, config_.period_us, config_.backend, hits_.probe_offset()};
  if (c.name.empty()) {
    std::string all;
    for (const auto& p : param_table()) all += (all.empty() ? "" : " ") + std::string(p.name) + " " + param_text(p, at);
    reply(s, slot, format_ok("Get", all));
    return;
  }
  const ParamSpec* p = find_param(c.name);
  if (!p) {
    reply(s, slot, unknown_param(c.name));
    return;
  }
  reply(s, slot, format_ok("Get", std::string(p->name) + " " + param_text(*p, at)));
}

void MessdDispatch::set_param(Session& s, std::uint32_t slot, const protocol::Set& c) {
  const ParamSpec* p = find_param(c.name);
  if (!p) {
    reply(s, slot, unknown_param(c.name));
    return;
  }
  if (p->read_only) {
    reply(s, slot, format_err(ErrorCode::ReadOnlyParameter, std::string(p->name) + " can be read but not set: " +
                                                                std::string(p->help) + "; Get reads it"));
    return;
  }
  std::string error;
  auto v = parse_param_value(*p, c.value, error);
  if (!v) {  // not a number at all is BadNumber, a number out of range BadValue
    reply(s, slot, format_err(protocol::parse_number(c.value) ? ErrorCode::BadValue : ErrorCode::BadNumber, error));
    return;
  }
  spdlog::debug("client {} sets {} to {}", s.id(), p->name, *v);  // debug: a flood must not fill the disk
  ParamPlaces at{gateway_, config_.report_hz, config_.period_us, config_.backend, hits_.probe_offset()};
  store_param(*p, at, *v);
  reply(s, slot, format_ok("Set"));
}

// Qualify radius form dx dy dz: TipRadius through the parameter lane (as Set does, so the
// next hit already uses it) and the probe offset here, then the Qualified event to everyone.
void MessdDispatch::qualify(Session& s, std::uint32_t slot, const protocol::Qualify& c) {
  gateway_.set_param(core::ParamId::TipRadius, c.radius);
  hits_.probe_offset() = {c.offset.x, c.offset.y, c.offset.z};
  reply(s, slot, protocol::format_ok("Qualify"));
  std::string text = "TipRadius ";
  protocol::append_fixed(text, c.radius, 4);
  text += " Offset";
  for (double v : hits_.probe_offset()) {
    text += ' ';
    protocol::append_fixed(text, v, 4);
  }
  text += " Form ";
  protocol::append_fixed(text, c.form, 4);
  sessions_.broadcast(protocol::format_event("Qualified", text));
}

// Verdict part in out result: passed on to everyone as the Inspected event (the MQTT bridge
// publishes it; a panel shows it). It changes nothing on the machine.
void MessdDispatch::verdict(Session& s, std::uint32_t slot, const protocol::Verdict& c) {
  reply(s, slot, protocol::format_ok("Verdict"));
  sessions_.broadcast(protocol::format_event("Inspected", c.part + " " + std::to_string(c.in) + " " + std::to_string(c.out) +
                                                              (c.pass ? " pass" : " fail")));
}

std::string MessdDispatch::status_line() {
  const auto& snap = gateway_.snapshot();
  std::string limits;
  const int n = layout().count;
  for (int a = 0; a < n; ++a)
    if (snap.limit[a] != 0)
      limits += (limits.empty() ? "" : ",") + std::string(1, layout().letters[a]) + (snap.limit[a] < 0 ? "neg" : "pos");
  std::string line = "State " + std::string(mode_name(snap.mode)) + " Pos";  // every axis, in the machine's order
  for (int a = 0; a < n; ++a) {
    line.push_back(' ');
    protocol::append_mm(line, snap.position[a]);
  }
  line += std::string(" Loops ") + (snap.loops_closed ? "closed" : "open");
  line += std::string(" Tip ") + (snap.tip_touched ? "touched" : "free");
  line += " Limits " + (limits.empty() ? std::string("none") : limits);
  line += std::string(" Homed ") + (snap.homed ? "yes" : "no");
  line += std::string(" Referenced ") + (snap.referenced ? "yes" : "no");
  line += " TipRadius " + fixed(snap.params.tip_radius) + " SpeedLevel " + fixed(snap.params.speed_level);
  line += " Clients " + std::to_string(sessions_.size());
  line += " Control " + status_value(control_.owner());  // appended last: the 1996-era prefix stays as it was
  return line;
}

}  // namespace imess::net
