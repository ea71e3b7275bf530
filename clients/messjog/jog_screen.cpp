// Drawing of the jog panel. Layout (top to bottom): title and link, positions, speed and
// motion, key map, messages (wrapped to the width) filling the rest of the terminal.
#define NCURSES_NOMACROS
#include "jog_screen.hpp"

#include <curses.h>

#include <algorithm>
#include <clocale>
#include <cstdio>
#include <string>

#include "key_map.hpp"
#include "note_rows.hpp"

namespace imess::messjog {
namespace {

std::string coordinates(const std::optional<Xyz>& p, const char* none) {
  if (!p) return none;
  char buf[96];
  std::snprintf(buf, sizeof buf, "%11.3f %11.3f %11.3f", p->x, p->y, p->z);
  return buf;
}

void put(int row, int col, const std::string& text, attr_t attr = A_NORMAL) {
  if (row >= LINES) return;
  attron(attr);
  mvaddnstr(row, col, text.c_str(), std::max(0, COLS - col));
  attroff(attr);
}

}  // namespace

JogScreen::JogScreen() {
  std::setlocale(LC_ALL, "");
  initscr();
  raw();
  noecho();
  keypad(stdscr, TRUE);
  nodelay(stdscr, TRUE);
  curs_set(0);
  set_escdelay(25);
}

JogScreen::~JogScreen() { endwin(); }

int JogScreen::read_key() {
  int key = getch();
  return key == ERR ? -1 : key;
}

void JogScreen::draw(const JogSession& session) {
  const JogPanel& panel = session.panel();
  const auto& link = session.link();
  erase();
  put(0, 0, "IMESS jog panel   messd " + link.endpoint().to_string(), A_BOLD);
  std::string state;
  if (panel.connected()) {
    state = "connected";
  } else {
    state = "reconnecting...";
    if (!link.last_error().empty()) state += " (" + link.last_error() + ")";
  }
  put(1, 0, "link: ");
  put(1, 6, state, panel.connected() ? A_BOLD : A_REVERSE);
  put(1, 48, "machine: ");
  put(1, 57, panel.machine_state(), panel.machine_state() == "fault" ? A_REVERSE : A_BOLD);
  put(2, 48, "control: ");
  put(2, 57, panel.controller());

  put(3, 0, "                            X           Y           Z");
  put(4, 0, "Current position   " + coordinates(panel.current(), "          -"),
      panel.connected() ? A_BOLD : A_DIM);
  put(5, 0, "Last measured      " + coordinates(panel.last_measured(), "          -") +
                (panel.points_measured() == 1   ? std::string("   (1 point)")
                 : panel.points_measured() > 1 ? "   (" + std::to_string(panel.points_measured()) + " points)"
                                               : std::string()));
  put(6, 0, "Marked             " + coordinates(panel.mark(), "          -   (k marks here)"));

  std::string speeds = "Speed  ";
  for (double level : kSpeedLevels) {
    char buf[16];
    bool on = level == panel.speed_percent();
    std::snprintf(buf, sizeof buf, on ? "[%g %%] " : " %g %%  ", level);
    speeds += buf;
  }
  put(8, 0, speeds);
  put(8, 36, "Motion: ");
  put(8, 44, panel.motion_text(), panel.moving() ? A_REVERSE : A_NORMAL);

  int row = 10;
  for (auto line : key_help()) put(row++, 0, std::string(line), A_DIM);

  ++row;
  put(row++, 0, "Messages", A_UNDERLINE);
  // Wrapped, never cut at the right edge: the newest at the bottom, as many as fit.
  for (const auto& text : note_rows(panel.notes(), COLS - 3, std::max(0, LINES - row))) put(row++, 2, text);
  refresh();
}

}  // namespace imess::messjog
