// messd's command line: the 1996 flags with their 1996 meaning, plus file and network options.
#pragma once
#include <optional>
#include <string>

namespace imess::app {

struct CliOptions {
  std::optional<std::string> config, rc, listen, journal, programs, frames, device;
  std::optional<int> port, ippdme_port, http_port;
  bool debug_comm = false, debug_motion = false, debug_status = false, timing = false;
  bool reboot = false, home = false, no_realtime = false, version = false, help = false;
};

// Throws std::invalid_argument with a message saying what was wrong and what is accepted.
CliOptions parse_cli(int argc, char** argv);
const char* usage_text();

}  // namespace imess::app
