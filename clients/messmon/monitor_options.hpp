// messmon's command line.
#pragma once
#include <string>

#include "imess/client/endpoint.hpp"

namespace imess::messmon {

struct MonitorOptions {
  client::Endpoint endpoint;
  bool json = false;
  bool reconnect = false;  // keep going across messd restarts instead of exiting
  bool help = false;
};

// Throws client::UsageError naming the bad argument and what is accepted.
MonitorOptions parse_monitor_options(int argc, const char* const argv[]);

std::string monitor_usage();

}  // namespace imess::messmon
