// The jog panel's keyboard: key code (as ncurses getch() returns it) -> JogAction, and the
// key map text the screen shows. Kept apart from drawing so the tests can check it.
#pragma once
#include <string_view>
#include <vector>

#include "jog_action.hpp"

namespace imess::messjog {

JogAction action_for_key(int key);

// One line per row of the on-screen key map (also used by --help).
const std::vector<std::string_view>& key_help();

}  // namespace imess::messjog
