// messjog's command line and --help text.
#include "jog_options.hpp"

#include <string_view>

#include "imess/client/usage_error.hpp"
#include "key_map.hpp"

namespace imess::messjog {

JogOptions parse_jog_options(int argc, const char* const argv[]) {
  JogOptions o;
  bool have_host = false;
  for (int i = 1; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--wait") {
      o.wait = true;
    } else if (a.size() > 1 && a.front() == '-') {
      throw client::UsageError("unknown option '" + std::string(a) + "'; accepted: --wait, --help");
    } else {
      client::take_host_argument(a, o.endpoint, have_host);
    }
  }
  return o;
}

std::string jog_usage() {
  std::string s =
      "usage: messjog [HOST[:PORT]] [--wait]\n"
      "The IMESS jog panel: jog the machine, measure, mark a position and move obliquely\n"
      "toward or away from the mark. HOST defaults to localhost, PORT to 1066.\n"
      "\n"
      "  --wait     start even if messd is not running yet (otherwise: exit 1)\n"
      "  -h, --help this text\n"
      "\n"
      "Keys:\n";
  for (auto line : key_help()) s.append("  ").append(line).append("\n");
  s +=
      "\n"
      "The panel reconnects by itself when messd restarts; the mark is kept.\n"
      "Exit status: 0 after q, 1 when messd cannot be reached at start, 2 on bad arguments.\n";
  return s;
}

}  // namespace imess::messjog
