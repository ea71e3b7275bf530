// JogScreen: the ncurses face of the jog panel — it draws a JogSession and reads keys, nothing more.
#pragma once

#include "jog_session.hpp"

namespace imess::messjog {

class JogScreen {
 public:
  JogScreen();   // takes over the terminal (raw mode: Ctrl-C arrives as a key, not a signal)
  ~JogScreen();  // gives it back
  JogScreen(const JogScreen&) = delete;
  JogScreen& operator=(const JogScreen&) = delete;

  // The next key, or -1 when none is waiting (never blocks).
  int read_key();
  void draw(const JogSession& session);
};

}  // namespace imess::messjog
