// JogPanel: the jog panel's logic without a screen — key actions to command lines, messages
// from messd to displayed state, the mark and the oblique-move line. The ncurses layer only
// draws what this holds; the tests drive it directly.
#pragma once
#include <chrono>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "imess/protocol/commands.hpp"
#include "jog_action.hpp"

namespace imess::messjog {

using protocol::Xyz;

inline constexpr double kSpeedLevels[] = {2.0, 20.0, 100.0};  // percent, as the 1996 panel
inline constexpr std::chrono::seconds kHomeConfirmWindow{3};
inline constexpr std::size_t kMaxNotes = 50;
// Dead-man: messd stops the machine when messjog, in control, is silent this long (Watch);
// while the machine moves messjog sends a blank line every kKeepAliveMoving, otherwise every
// kKeepAliveIdle (so messd never drops it as a silent controller).
inline constexpr int kWatchMs = 500;
inline constexpr std::chrono::milliseconds kKeepAliveMoving{100};
inline constexpr std::chrono::seconds kKeepAliveIdle{30};

class JogPanel {
 public:
  using Clock = std::chrono::steady_clock;

  // The command lines (without '\n') to send for an action, in order; often one, maybe none.
  // Operator feedback (refusals, hints) goes to notes().
  std::vector<std::string> act(JogAction action, Clock::time_point now = Clock::now());

  // A line received from messd.
  void on_line(std::string_view line);

  // The link came up: returns the lines to send first (Hello, Watch, Status). Motion and
  // pending replies reset.
  std::vector<std::string> on_connected(std::string_view where);
  void on_disconnected(std::string_view reason);

  // ---- what the screen shows ----
  bool connected() const { return connected_; }
  const std::optional<Xyz>& current() const { return current_; }
  const std::optional<Xyz>& last_measured() const { return last_measured_; }
  const std::optional<Xyz>& mark() const { return mark_; }
  int points_measured() const { return points_; }
  const std::string& machine_state() const { return machine_state_; }  // "?" until a State event
  double speed_percent() const { return speed_percent_; }
  bool moving() const { return motion_.has_value(); }
  std::string motion_text() const;  // "stopped", "+X at 20 %", "toward mark at 2 %"
  const std::deque<std::string>& notes() const { return notes_; }  // oldest first
  const std::string& controller() const { return controller_; }     // "messjog 127.0.0.1", "none", "?"
  // How often to send a keep-alive (a blank line) now: fast while the machine moves.
  std::chrono::milliseconds keepalive_interval() const;
  bool quit_requested() const { return quit_; }

 private:
  struct Motion {
    JogAction action;  // the key that started it (pressing it again stops)
    Xyz unit;          // direction, kept while the speed level changes
  };

  std::vector<std::string> start(JogAction action, const Xyz& unit);
  std::vector<std::string> stop();
  std::vector<std::string> oblique(JogAction action);
  std::vector<std::string> send(std::string line);
  void note(std::string text);
  void reply_received(bool ok, std::string_view text, int code);

  bool connected_ = false;
  std::optional<Xyz> current_, last_measured_, mark_;
  std::optional<Xyz> line_;  // unit(current - mark) fixed by the first oblique key; an axis key or a new mark clears it
  std::optional<Motion> motion_;
  std::string machine_state_ = "?";
  std::string controller_ = "?";  // from the Control event and Status
  double speed_percent_ = kSpeedLevels[1];
  int points_ = 0;
  std::deque<std::string> pending_;  // verbs sent and not yet answered (Ok/Err come in order)
  std::deque<std::string> notes_;
  std::optional<Clock::time_point> home_armed_until_, take_armed_until_;
  bool quit_ = false;
};

}  // namespace imess::messjog
