// messjog's logic without a terminal: key action -> exact command line, the oblique move,
// state from messd's lines, replies, the home confirmation and quitting.
#include <catch2/catch.hpp>

#include "jog_panel.hpp"
#include "note_rows.hpp"
#include "key_map.hpp"

using namespace imess::messjog;
using Lines = std::vector<std::string>;

namespace {

JogPanel connected_panel(const std::string& position = "CurrCor 3.000 4.000 0.000") {
  JogPanel p;
  p.on_connected("127.0.0.1:1066");
  p.on_line(position);
  return p;
}

bool noted(const JogPanel& p, const std::string& part) {
  for (const auto& n : p.notes())
    if (n.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("JogPanel: greets with Hello, arms the dead-man with Watch and asks for the Status on connect") {
  JogPanel p;
  CHECK(p.on_connected("localhost:1066") == Lines{"Hello messjog", "Watch 500", "Status"});
  CHECK(p.connected());
  CHECK(p.machine_state() == "?");
  p.on_line("Ok Hello IMESS 1");
  p.on_line("Ok Watch");
  p.on_line("Ok Status State free Pos 1.000 2.000 3.000 Loops open");
  CHECK(p.machine_state() == "free");
  p.on_line("State idle");
  CHECK(p.machine_state() == "idle");
}

TEST_CASE("JogPanel: each axis key sends StartMv at the selected speed, 3 decimals") {
  auto p = connected_panel();
  CHECK(p.speed_percent() == 20.0);  // middle level by default
  CHECK(p.act(JogAction::XPlus) == Lines{"StartMv 20.000 0.000 0.000"});
  CHECK(p.act(JogAction::XMinus) == Lines{"StartMv -20.000 0.000 0.000"});
  CHECK(p.act(JogAction::YPlus) == Lines{"StartMv 0.000 20.000 0.000"});
  CHECK(p.act(JogAction::YMinus) == Lines{"StartMv 0.000 -20.000 0.000"});
  CHECK(p.act(JogAction::ZPlus) == Lines{"StartMv 0.000 0.000 20.000"});
  CHECK(p.act(JogAction::ZMinus) == Lines{"StartMv 0.000 0.000 -20.000"});
  CHECK(p.moving());
  CHECK(p.motion_text() == "-Z at 20 %");
}

TEST_CASE("JogPanel: speed levels 2/20/100 % - changing speed while jogging re-sends the jog") {
  auto p = connected_panel();
  CHECK(p.act(JogAction::Speed1).empty());  // not moving: just selects
  CHECK(p.act(JogAction::YPlus) == Lines{"StartMv 0.000 2.000 0.000"});
  CHECK(p.act(JogAction::Speed3) == Lines{"StartMv 0.000 100.000 0.000"});
  CHECK(p.act(JogAction::Speed2) == Lines{"StartMv 0.000 20.000 0.000"});
  CHECK(p.motion_text() == "+Y at 20 %");
}

TEST_CASE("JogPanel: space stops, and so does the same jog key again") {
  auto p = connected_panel();
  p.act(JogAction::XPlus);
  CHECK(p.act(JogAction::XPlus) == Lines{"StopMv"});
  CHECK_FALSE(p.moving());
  p.act(JogAction::ZMinus);
  CHECK(p.act(JogAction::Stop) == Lines{"StopMv"});
  CHECK_FALSE(p.moving());
  CHECK(p.act(JogAction::Stop) == Lines{"StopMv"});  // stopping is never refused
  CHECK(p.motion_text() == "stopped");
}

TEST_CASE("JogPanel: another direction key replaces the running jog") {
  auto p = connected_panel();
  p.act(JogAction::XPlus);
  CHECK(p.act(JogAction::YMinus) == Lines{"StartMv 0.000 -20.000 0.000"});
  CHECK(p.motion_text() == "-Y at 20 %");
}

TEST_CASE("JogPanel: m measures here") {
  auto p = connected_panel();
  CHECK(p.act(JogAction::Measure) == Lines{"ForcePt"});
}

TEST_CASE("JogPanel: Enter, Del and F1-F4 send the inspection software's keys") {
  auto p = connected_panel();
  CHECK(p.act(JogAction::KeyDone) == Lines{"Key Done"});
  CHECK(p.act(JogAction::KeyDel) == Lines{"Key Del"});
  CHECK(p.act(JogAction::KeyF1) == Lines{"Key F1"});
  CHECK(p.act(JogAction::KeyF4) == Lines{"Key F4"});
}

TEST_CASE("JogPanel: oblique move toward and away from the mark (brief example)") {
  JogPanel p = connected_panel("CurrCor 0.000 0.000 0.000");
  CHECK(p.act(JogAction::Mark).empty());  // client side only
  REQUIRE(p.mark() == Xyz{0, 0, 0});
  p.on_line("CurrCor 3.000 4.000 0.000");
  CHECK(p.act(JogAction::TowardMark) == Lines{"StartMv -12.000 -16.000 0.000"});
  CHECK(p.motion_text() == "toward mark at 20 %");
  CHECK(p.act(JogAction::AwayFromMark) == Lines{"StartMv 12.000 16.000 0.000"});
  CHECK(p.act(JogAction::Speed3) == Lines{"StartMv 60.000 80.000 0.000"});
  CHECK(p.act(JogAction::AwayFromMark) == Lines{"StopMv"});  // same key again
}

TEST_CASE("JogPanel: oblique direction in 3-D and with a mark away from the origin") {
  JogPanel p = connected_panel("CurrCor 1.000 2.000 3.000");
  p.act(JogAction::Mark);
  p.on_line("CurrCor 3.000 5.000 9.000");  // d = (2, 3, 6), |d| = 7
  CHECK(p.act(JogAction::TowardMark) == Lines{"StartMv -5.714 -8.571 -17.143"});
  p.act(JogAction::Speed3);
  p.act(JogAction::Stop);
  CHECK(p.act(JogAction::AwayFromMark) == Lines{"StartMv 28.571 42.857 85.714"});
}

TEST_CASE("JogPanel: the oblique line stays fixed until an axis key is used") {
  JogPanel p = connected_panel("CurrCor 0.000 0.000 0.000");
  p.act(JogAction::Mark);
  p.on_line("CurrCor 3.000 4.000 0.000");
  p.act(JogAction::TowardMark);
  p.on_line("CurrCor 1.500 2.100 0.000");  // drifted a little off the line
  p.act(JogAction::Stop);
  CHECK(p.act(JogAction::TowardMark) == Lines{"StartMv -12.000 -16.000 0.000"});  // same line
  p.on_line("CurrCor -3.000 -4.000 0.000");  // overshot the mark: "toward" turns back along the line
  CHECK(p.act(JogAction::Speed2) == Lines{"StartMv -12.000 -16.000 0.000"});  // a speed change keeps the motion
  p.act(JogAction::Stop);
  CHECK(p.act(JogAction::TowardMark) == Lines{"StartMv 12.000 16.000 0.000"});

  p.act(JogAction::XPlus);  // an axis key ends the line...
  p.on_line("CurrCor 4.000 4.000 0.000");
  p.act(JogAction::Stop);
  // ...so the next oblique key takes the new line through mark and current position
  CHECK(p.act(JogAction::TowardMark) == Lines{"StartMv -14.142 -14.142 0.000"});
}

TEST_CASE("JogPanel: oblique keys refuse without a mark or at the mark, and say why") {
  JogPanel p = connected_panel();
  CHECK(p.act(JogAction::TowardMark).empty());
  CHECK(noted(p, "no mark"));
  p.act(JogAction::Mark);
  CHECK(p.act(JogAction::AwayFromMark).empty());
  CHECK(noted(p, "stands at the mark"));
  p.on_line("CurrCor 3.000 0.000 0.000");  // jogged -Y from the mark at (3, 4, 0)
  CHECK(p.act(JogAction::TowardMark) == Lines{"StartMv 0.000 20.000 0.000"});
  p.on_line("CurrCor 3.000 4.000 0.000");  // a new mark clears the line
  p.act(JogAction::Mark);
  p.act(JogAction::Stop);
  CHECK(p.act(JogAction::TowardMark).empty());
}

TEST_CASE("JogPanel: messd's lines update positions, state and messages") {
  JogPanel p = connected_panel();
  CHECK(p.current() == Xyz{3, 4, 0});
  CHECK_FALSE(p.last_measured());
  p.on_line("MeasPt 1.500 -2.000 3.250");
  p.on_line("MeasPt 1.000 1.000 1.000");
  CHECK(p.last_measured() == Xyz{1, 1, 1});
  CHECK(p.points_measured() == 2);
  p.on_line("State free");
  CHECK(p.machine_state() == "free");
  p.on_line("Warn TipNotFree Could not free the tip automatically, do it by hand");
  CHECK(noted(p, "Warn TipNotFree: Could not free the tip automatically, do it by hand"));
  p.on_line("Limit X pos");
  CHECK(noted(p, "limit switch X pos"));
  p.on_line("Fault Drive drive not ready");
  CHECK(noted(p, "FAULT Drive: drive not ready"));
  p.on_line("Ok Hello IMESS 1 sim");
  CHECK(noted(p, "messd: IMESS 1 sim"));
  p.on_line("this is not a message");  // ignored
  p.on_line("CurrCor 1 2");            // malformed: ignored, position kept
  CHECK(p.current() == Xyz{3, 4, 0});
}

TEST_CASE("JogPanel: an Err to StartMv ends the jog and names the refused command") {
  JogPanel p = connected_panel();
  p.on_line("Ok Hello IMESS 1");
  p.on_line("Ok Watch");
  p.on_line("Ok Status State idle");
  p.act(JogAction::XPlus);
  REQUIRE(p.moving());
  p.on_line("Err 200 Tip is touched, can't move - move the tip by hand");
  CHECK_FALSE(p.moving());
  CHECK(noted(p, "StartMv refused: Err 200 Tip is touched"));
}

TEST_CASE("JogPanel: a State other than jog ends the jog, but not before StartMv is answered") {
  JogPanel p = connected_panel();
  p.on_line("Ok Hello IMESS 1");
  p.on_line("Ok Watch");
  p.on_line("Ok Status State idle");
  p.act(JogAction::XPlus);
  p.on_line("State idle");  // sent before messd saw our StartMv
  CHECK(p.moving());
  p.on_line("Ok StartMv");
  p.on_line("State jog");
  CHECK(p.moving());
  p.on_line("State idle");  // stopped by a limit switch, say
  CHECK_FALSE(p.moving());
}

TEST_CASE("JogPanel: home needs a second h within 3 s") {
  JogPanel p = connected_panel();
  auto t0 = JogPanel::Clock::time_point{} + std::chrono::hours(1);
  CHECK(p.act(JogAction::Home, t0).empty());
  CHECK(noted(p, "press h again"));
  CHECK(p.act(JogAction::Home, t0 + std::chrono::seconds(1)) == Lines{"Home"});
  CHECK(p.act(JogAction::Home, t0 + std::chrono::seconds(10)).empty());  // re-armed, not sent
  CHECK(p.act(JogAction::Home, t0 + std::chrono::seconds(14)).empty());  // too late: armed again
  p.act(JogAction::Measure, t0 + std::chrono::seconds(15));              // another key disarms
  CHECK(p.act(JogAction::Home, t0 + std::chrono::seconds(16)).empty());
}

TEST_CASE("JogPanel: q stops a running jog before quitting") {
  JogPanel moving = connected_panel();
  moving.act(JogAction::ZPlus);
  CHECK(moving.act(JogAction::Quit) == Lines{"StopMv"});
  CHECK(moving.quit_requested());
  CHECK(moving.act(JogAction::XPlus).empty());  // nothing after quit

  JogPanel idle = connected_panel();
  CHECK(idle.act(JogAction::Quit).empty());
  CHECK(idle.quit_requested());

  JogPanel other = connected_panel();  // jogging on another client's command: stop it too
  other.on_line("State jog");
  CHECK(other.act(JogAction::Quit) == Lines{"StopMv"});
}

TEST_CASE("JogPanel: while disconnected keys send nothing - the mark survives a reconnect") {
  JogPanel p = connected_panel();
  p.act(JogAction::Mark);
  p.act(JogAction::XPlus);
  p.on_disconnected("closed by messd");
  CHECK_FALSE(p.connected());
  CHECK_FALSE(p.moving());
  CHECK(p.machine_state() == "?");
  CHECK(p.act(JogAction::XPlus).empty());
  CHECK(p.act(JogAction::Measure).empty());
  CHECK(noted(p, "connection lost (closed by messd)"));
  CHECK(p.on_connected("127.0.0.1:1066") == Lines{"Hello messjog", "Watch 500", "Status"});
  CHECK(p.mark() == Xyz{3, 4, 0});
}

TEST_CASE("Key map: letters, digits and space") {
  CHECK(action_for_key('a') == JogAction::XMinus);
  CHECK(action_for_key('d') == JogAction::XPlus);
  CHECK(action_for_key('s') == JogAction::YMinus);
  CHECK(action_for_key('w') == JogAction::YPlus);
  CHECK(action_for_key('f') == JogAction::ZMinus);
  CHECK(action_for_key('r') == JogAction::ZPlus);
  CHECK(action_for_key('W') == JogAction::YPlus);
  CHECK(action_for_key('1') == JogAction::Speed1);
  CHECK(action_for_key('2') == JogAction::Speed2);
  CHECK(action_for_key('3') == JogAction::Speed3);
  CHECK(action_for_key(' ') == JogAction::Stop);
  CHECK(action_for_key('m') == JogAction::Measure);
  CHECK(action_for_key('k') == JogAction::Mark);
  CHECK(action_for_key('o') == JogAction::TowardMark);
  CHECK(action_for_key('p') == JogAction::AwayFromMark);
  CHECK(action_for_key('h') == JogAction::Home);
  CHECK(action_for_key('t') == JogAction::TakeOver);
  CHECK(action_for_key('\n') == JogAction::KeyDone);
  CHECK(action_for_key(127) == JogAction::KeyDel);
  CHECK(action_for_key('q') == JogAction::Quit);
  CHECK(action_for_key(3) == JogAction::Quit);  // Ctrl-C in raw mode
  CHECK(action_for_key('x') == JogAction::None);
}

TEST_CASE("JogPanel: shows who controls the machine and explains NotInControl") {
  auto p = connected_panel();
  p.on_line("Ok Hello IMESS 1");
  p.on_line("Ok Watch");
  p.on_line("Ok Status State idle Pos 0.000 0.000 0.000 Clients 2 Control telnet@10.0.0.7");
  CHECK(p.controller() == "telnet@10.0.0.7");
  CHECK(p.act(JogAction::XPlus) == Lines{"StartMv 20.000 0.000 0.000"});
  p.on_line("Err 209 the machine is controlled by telnet at 10.0.0.7 (client 4); StopMv is open to all");
  CHECK_FALSE(p.moving());
  CHECK(noted(p, "telnet at 10.0.0.7"));
  CHECK(noted(p, "Space (stop) still works"));
  CHECK(noted(p, "your next key takes control"));  // the handover: the operator need not release it elsewhere
  p.on_line("Control none");
  CHECK(p.controller() == "none");
  p.on_line("Control messjog 127.0.0.1");
  CHECK(p.controller() == "messjog 127.0.0.1");
}

TEST_CASE("JogPanel: a forced take-over or the dead-man ends the jog shown") {
  auto p = connected_panel();
  p.on_line("Ok Hello IMESS 1");
  p.on_line("Ok Watch");
  p.on_line("Ok Status State idle");
  p.act(JogAction::YPlus);
  p.on_line("State jog");
  p.on_line("Ok StartMv");
  REQUIRE(p.moving());
  CHECK(p.keepalive_interval() == kKeepAliveMoving);
  p.on_line("Warn ControlTaken operator 127.0.0.1 took over; machine stopped");
  CHECK_FALSE(p.moving());
  CHECK(noted(p, "ControlTaken"));
}

TEST_CASE("JogPanel: keep-alives are fast only while something moves or waits for an answer") {
  auto p = connected_panel();
  CHECK(p.keepalive_interval() == kKeepAliveMoving);  // Hello, Watch, Status unanswered
  p.on_line("Ok Hello IMESS 1");
  p.on_line("Ok Watch");
  p.on_line("Ok Status State idle");
  CHECK(p.keepalive_interval() == kKeepAliveIdle);
  p.on_line("State move");  // another move (GoTo from this panel's owner, or Home)
  CHECK(p.keepalive_interval() == kKeepAliveMoving);
  p.on_line("State free");
  CHECK(p.keepalive_interval() == kKeepAliveIdle);
}

TEST_CASE("JogPanel: t t takes control over (Take force), a single t only asks for confirmation") {
  auto p = connected_panel();
  auto t0 = JogPanel::Clock::now();
  CHECK(p.act(JogAction::TakeOver, t0).empty());
  CHECK(noted(p, "press t again"));
  CHECK(p.act(JogAction::TakeOver, t0 + std::chrono::seconds(1)) == Lines{"Take force"});
  CHECK(p.act(JogAction::TakeOver, t0 + std::chrono::seconds(2)).empty());  // armed again, not sent
  CHECK(p.act(JogAction::TakeOver, t0 + std::chrono::seconds(6)).empty());  // too late: asks again
}

TEST_CASE("JogPanel messages wrap at the terminal's width, nothing is cut off") {
  const std::string refusal =
      "StartMv refused: Err 209 the machine is controlled by telnet at 127.0.0.1 (client 3); StopMv is open to all, "
      "Status shows the owner";
  const auto rows = wrap_message(refusal, 40);
  REQUIRE(rows.size() > 2);
  std::string joined;
  for (const auto& r : rows) {
    CHECK(r.size() <= 40);
    joined += (joined.empty() ? "" : " ") + r.substr(r.rfind("  ", 0) == 0 ? 2 : 0);
  }
  CHECK(joined == refusal);  // every word, in order: "StopMv is open" is not cut to "StopMv is o"
  CHECK(rows[1].rfind("  ", 0) == 0);  // continuation rows are indented
  // A word longer than a row is broken, not lost.
  const auto long_word = wrap_message(std::string(25, 'x'), 10);
  REQUIRE(long_word.size() == 3);
  CHECK(long_word[0] == std::string(10, 'x'));
  CHECK(long_word[1] == "  " + std::string(8, 'x'));
  CHECK(long_word[2] == "  " + std::string(7, 'x'));
  CHECK(wrap_message("", 40) == std::vector<std::string>{""});
  // The newest rows fill the area from the bottom.
  std::deque<std::string> notes{"first", refusal, "last"};
  const auto shown = note_rows(notes, 40, 3);
  REQUIRE(shown.size() == 3);
  CHECK(shown.back() == "last");
  CHECK(shown[0] == rows[rows.size() - 2]);
  CHECK(note_rows(notes, 40, 100).front() == "first");
}
