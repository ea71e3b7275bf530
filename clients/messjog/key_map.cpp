// Key layout: arrows or a/d w/s for X and Y (screen left/right = X, up/down = Y), PgUp/PgDn
// or r/f for Z, so either hand position works and the letters need no special keys.
#define NCURSES_NOMACROS
#include "key_map.hpp"

#include <curses.h>

namespace imess::messjog {

JogAction action_for_key(int key) {
  switch (key) {
    case KEY_LEFT: case 'a': case 'A': return JogAction::XMinus;
    case KEY_RIGHT: case 'd': case 'D': return JogAction::XPlus;
    case KEY_DOWN: case 's': case 'S': return JogAction::YMinus;
    case KEY_UP: case 'w': case 'W': return JogAction::YPlus;
    case KEY_NPAGE: case 'f': case 'F': return JogAction::ZMinus;
    case KEY_PPAGE: case 'r': case 'R': return JogAction::ZPlus;
    case ' ': return JogAction::Stop;
    case '1': return JogAction::Speed1;
    case '2': return JogAction::Speed2;
    case '3': return JogAction::Speed3;
    case 'm': case 'M': return JogAction::Measure;
    case 'k': case 'K': return JogAction::Mark;
    case 'o': case 'O': return JogAction::TowardMark;
    case 'p': case 'P': return JogAction::AwayFromMark;
    case 'h': case 'H': return JogAction::Home;
    case 't': case 'T': return JogAction::TakeOver;
    case '\n': case '\r': case KEY_ENTER: return JogAction::KeyDone;
    case KEY_BACKSPACE: case KEY_DC: case 127: return JogAction::KeyDel;
    case KEY_F(1): return JogAction::KeyF1;
    case KEY_F(2): return JogAction::KeyF2;
    case KEY_F(3): return JogAction::KeyF3;
    case KEY_F(4): return JogAction::KeyF4;
    case 'q': case 'Q': case 3 /* Ctrl-C in raw mode */: return JogAction::Quit;
    default: return JogAction::None;
  }
}

const std::vector<std::string_view>& key_help() {
  static const std::vector<std::string_view> lines = {
      "Left/a  -X    Right/d  +X    Down/s  -Y    Up/w  +Y    PgDn/f  -Z    PgUp/r  +Z",
      "1 2 3   speed 2 / 20 / 100 %          Space  stop (or press the same key again)",
      "m  measure here (ForcePt)    k  mark here    o  toward mark    p  away from mark",
      "h h  home (press twice)      t t  take control over (press twice)    q  quit",
      "Enter Del F1-F4  keys for the inspection software (I++ DME) when it enabled you",
      "A jog runs until stopped or another direction key: terminals report no key release.",
  };
  return lines;
}

}  // namespace imess::messjog
