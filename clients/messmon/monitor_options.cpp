// messmon's command line and --help text.
#include "monitor_options.hpp"

#include <string_view>

#include "imess/client/usage_error.hpp"

namespace imess::messmon {

MonitorOptions parse_monitor_options(int argc, const char* const argv[]) {
  MonitorOptions o;
  bool have_host = false;
  for (int i = 1; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--json") {
      o.json = true;
    } else if (a == "--reconnect") {
      o.reconnect = true;
    } else if (a.size() > 1 && a.front() == '-') {
      throw client::UsageError("unknown option '" + std::string(a) +
                               "'; accepted: --json, --reconnect, --help");
    } else {
      client::take_host_argument(a, o.endpoint, have_host);
    }
  }
  return o;
}

std::string monitor_usage() {
  return "usage: messmon [HOST[:PORT]] [--json] [--reconnect]\n"
         "Prints every line messd sends, one per line, prefixed with the local time\n"
         "(ISO 8601 with milliseconds). HOST defaults to localhost, PORT to 1066.\n"
         "messmon sends one line itself, 'Hello messmon'; its reply is printed too.\n"
         "\n"
         "  --json       one JSON object per line instead:\n"
         "               {\"t\":\"2024-05-01T14:03:07.042+02:00\",\"line\":\"MeasPt 1.000 2.000 3.000\",\n"
         "                \"type\":\"MeasPt\",\"x\":1.0,\"y\":2.0,\"z\":3.0}\n"
         "               types: CurrCor MeasPt (x y z), State (state), Limit (axis side),\n"
         "               Warn Fault (name text), Homed, Ok (verb args), Err (code text),\n"
         "               Data (verb text), Other\n"
         "  --reconnect  when messd goes away, wait for it (retry every second)\n"
         "               instead of exiting\n"
         "  -h, --help   this text\n"
         "\n"
         "Exit status: 0 when messd closes the connection or on Ctrl-C (SIGINT/SIGTERM);\n"
         "1 when messd cannot be reached at start; 2 on bad arguments.\n"
         "Notices (connected, closed, reconnecting) go to stderr, the lines to stdout.\n";
}

}  // namespace imess::messmon
