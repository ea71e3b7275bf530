// JogPanel: the jog panel's behaviour, from key actions and received lines to state and commands.
#include "jog_panel.hpp"

#include <cmath>
#include <cstdio>
#include <type_traits>

#include "imess/protocol/messages.hpp"
#include "oblique.hpp"

namespace imess::messjog {
namespace {

struct AxisJog {
  JogAction action;
  Xyz unit;
  const char* label;
};
constexpr AxisJog kAxisJogs[] = {
    {JogAction::XMinus, {-1, 0, 0}, "-X"}, {JogAction::XPlus, {1, 0, 0}, "+X"},
    {JogAction::YMinus, {0, -1, 0}, "-Y"}, {JogAction::YPlus, {0, 1, 0}, "+Y"},
    {JogAction::ZMinus, {0, 0, -1}, "-Z"}, {JogAction::ZPlus, {0, 0, 1}, "+Z"},
};

const AxisJog* axis_jog(JogAction a) {
  for (const auto& j : kAxisJogs)
    if (j.action == a) return &j;
  return nullptr;
}

std::string percent_text(double percent) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g %%", percent);
  return buf;
}

std::string xyz_text(const Xyz& p) {
  std::string s = protocol::format_xyz("", p);  // " x y z\n"
  return s.substr(1, s.size() - 2);
}

std::string first_word(std::string_view line) {
  auto end = line.find(' ');
  return std::string(line.substr(0, end));
}

}  // namespace

std::vector<std::string> JogPanel::act(JogAction action, Clock::time_point now) {
  if (quit_) return {};
  bool confirm_home = action == JogAction::Home && home_armed_until_ && now <= *home_armed_until_;
  bool confirm_take = action == JogAction::TakeOver && take_armed_until_ && now <= *take_armed_until_;
  home_armed_until_.reset();
  take_armed_until_.reset();

  if (action == JogAction::Quit) {
    quit_ = true;
    if (connected_ && (motion_ || machine_state_ == "jog")) return stop();
    return {};
  }
  if (action == JogAction::Mark) {
    if (!connected_ || !current_) {
      note(connected_ ? "no position from messd yet: nothing to mark" : "not connected: the position shown may be stale, not marked");
      return {};
    }
    mark_ = current_;
    line_.reset();
    note("marked " + xyz_text(*mark_));
    return {};
  }
  if (action == JogAction::Speed1 || action == JogAction::Speed2 || action == JogAction::Speed3) {
    speed_percent_ = kSpeedLevels[action == JogAction::Speed1 ? 0 : action == JogAction::Speed2 ? 1 : 2];
    if (motion_ && connected_) return start(motion_->action, motion_->unit);  // same direction, new speed
    return {};
  }
  if (action == JogAction::None) return {};
  if (!connected_) {
    note("not connected to messd: key ignored");
    return {};
  }
  if (const AxisJog* jog = axis_jog(action)) {
    if (motion_ && motion_->action == action) return stop();  // the same key again stops
    line_.reset();  // an axis key ends the oblique line
    return start(action, jog->unit);
  }
  switch (action) {
    case JogAction::Stop: return stop();
    case JogAction::Measure: return send("ForcePt");
    case JogAction::KeyDone: return send("Key Done");
    case JogAction::KeyDel: return send("Key Del");
    case JogAction::KeyF1: return send("Key F1");
    case JogAction::KeyF2: return send("Key F2");
    case JogAction::KeyF3: return send("Key F3");
    case JogAction::KeyF4: return send("Key F4");
    case JogAction::TowardMark:
    case JogAction::AwayFromMark: return oblique(action);
    case JogAction::Home:
      if (!confirm_home) {
        home_armed_until_ = now + kHomeConfirmWindow;
        note("press h again within 3 s to home the machine");
        return {};
      }
      motion_.reset();
      return send("Home");
    case JogAction::TakeOver:
      if (!confirm_take) {
        take_armed_until_ = now + kHomeConfirmWindow;
        note("press t again within 3 s to take control over: messd stops the machine first");
        return {};
      }
      motion_.reset();
      return send("Take force");
    default: return {};
  }
}

std::vector<std::string> JogPanel::oblique(JogAction action) {
  if (!mark_) {
    note("no mark: press k at a position first, then jog away from it");
    return {};
  }
  if (!current_) {
    note("no position from messd yet");
    return {};
  }
  if (!line_) {
    line_ = unit_direction(*mark_, *current_);
    if (!line_) {
      note("the machine stands at the mark: jog away from it along the axes first");
      return {};
    }
  }
  if (motion_ && motion_->action == action) return stop();  // the same key again stops
  // Signed distance to the mark along the line decides which way "toward" is, also past the mark.
  Xyz to_mark{mark_->x - current_->x, mark_->y - current_->y, mark_->z - current_->z};
  double ahead = dot(to_mark, *line_);
  Xyz toward = ahead > 0 ? *line_ : Xyz{-line_->x, -line_->y, -line_->z};
  if (std::abs(ahead) < kSamePointMm) {
    if (action == JogAction::TowardMark) {
      note("already at the mark");
      return {};
    }
    toward = Xyz{-line_->x, -line_->y, -line_->z};  // away = back along the side it was approached from
  }
  Xyz unit = action == JogAction::TowardMark ? toward : Xyz{-toward.x, -toward.y, -toward.z};
  return start(action, unit);
}

std::vector<std::string> JogPanel::start(JogAction action, const Xyz& unit) {
  motion_ = Motion{action, unit};
  std::string line = protocol::format_xyz("StartMv", jog_speeds(unit, speed_percent_));
  line.pop_back();  // '\n'
  return send(std::move(line));
}

std::vector<std::string> JogPanel::stop() {
  motion_.reset();
  return send("StopMv");
}

std::vector<std::string> JogPanel::send(std::string line) {
  pending_.push_back(first_word(line));
  return {std::move(line)};
}

void JogPanel::note(std::string text) {
  notes_.push_back(std::move(text));
  while (notes_.size() > kMaxNotes) notes_.pop_front();
}

void JogPanel::reply_received(bool ok, std::string_view text, int code) {
  std::string verb = pending_.empty() ? std::string("?") : pending_.front();
  if (!pending_.empty()) pending_.pop_front();
  if (ok) return;
  note(verb + " refused: " + std::string(text));
  if (code == static_cast<int>(protocol::ErrorCode::NotInControl))
    note("another client controls the machine: once it leaves the machine at rest and sends nothing for "
         "messd's control.handover_s (2 s by default), your next key takes control; t t takes it now; "
         "Space (stop) still works from here");
  else if (code == static_cast<int>(protocol::ErrorCode::HostNotAllowed))
    note("this host may only watch and stop the machine (messd's control.hosts)");
  bool another_start_pending = false;
  for (const auto& v : pending_) another_start_pending |= v == "StartMv";
  if (verb == "StartMv" && !another_start_pending) motion_.reset();
}

void JogPanel::on_line(std::string_view line) {
  auto message = protocol::parse_message(line);
  std::visit(
      [&](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, protocol::CurrCorMsg>) {
          current_ = m.p;
        } else if constexpr (std::is_same_v<T, protocol::MeasPtMsg>) {
          last_measured_ = m.p;
          ++points_;
        } else if constexpr (std::is_same_v<T, protocol::StateMsg>) {
          machine_state_ = m.state;
          bool start_pending = false;
          for (const auto& v : pending_) start_pending |= v == "StartMv";
          if (m.state != "jog" && !start_pending) motion_.reset();  // stopped by a limit, a hit, another client
        } else if constexpr (std::is_same_v<T, protocol::LimitMsg>) {
          note("limit switch " + m.axis + " " + m.side);
        } else if constexpr (std::is_same_v<T, protocol::WarnMsg>) {
          if (m.name == "ControlTaken" || m.name == "WatchExpired") motion_.reset();  // messd stopped the machine
          note("Warn " + m.name + ": " + m.text);
        } else if constexpr (std::is_same_v<T, protocol::FaultMsg>) {
          motion_.reset();
          note("FAULT " + m.name + ": " + m.text);
        } else if constexpr (std::is_same_v<T, protocol::HomedMsg>) {
          note("homed");
        } else if constexpr (std::is_same_v<T, protocol::OkMsg>) {
          if (m.verb == "Hello") {
            std::string who = "messd:";
            for (const auto& a : m.args) who += " " + a;
            note(who);
          }
          if (m.verb == "Status")  // "Ok Status State idle Pos ...": the state until a State event
            for (std::size_t i = 0; i + 1 < m.args.size(); ++i) {
              if (m.args[i] == "State") machine_state_ = m.args[i + 1];
              if (m.args[i] == "Control") controller_ = m.args[i + 1];
            }
          reply_received(true, line, 0);
        } else if constexpr (std::is_same_v<T, protocol::ErrMsg>) {
          reply_received(false, line, m.code);
        } else if constexpr (std::is_same_v<T, protocol::OtherMsg>) {
          if (m.line.rfind("Control ", 0) == 0) controller_ = m.line.substr(8);  // "messjog 127.0.0.1" or "none"
        }
        // data lines and anything unknown: ignored, as every 1996 receiver did
      },
      message);
}

std::vector<std::string> JogPanel::on_connected(std::string_view where) {
  connected_ = true;
  pending_.clear();
  motion_.reset();
  machine_state_ = "?";
  note("connected to " + std::string(where));
  controller_ = "?";
  auto lines = send("Hello messjog");
  lines.push_back(send("Watch " + std::to_string(kWatchMs)).front());  // messd stops the machine if messjog dies or hangs
  lines.push_back(send("Status").front());  // messd pushes State only on changes
  return lines;
}

void JogPanel::on_disconnected(std::string_view reason) {
  if (connected_) note("connection lost (" + std::string(reason) + "): reconnecting");
  connected_ = false;
  controller_ = "?";
  pending_.clear();
  motion_.reset();
  machine_state_ = "?";
}

std::chrono::milliseconds JogPanel::keepalive_interval() const {
  const bool machine_moves = machine_state_ == "jog" || machine_state_ == "move" || machine_state_ == "retract" ||
                             machine_state_ == "home";
  if (motion_ || machine_moves || !pending_.empty()) return kKeepAliveMoving;
  return kKeepAliveIdle;
}

std::string JogPanel::motion_text() const {
  if (!motion_) return "stopped";
  std::string what;
  if (const AxisJog* jog = axis_jog(motion_->action))
    what = jog->label;
  else
    what = motion_->action == JogAction::TowardMark ? "toward mark" : "away from mark";
  return what + " at " + percent_text(speed_percent_);
}

}  // namespace imess::messjog
