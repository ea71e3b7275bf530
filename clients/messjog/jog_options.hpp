// messjog's command line.
#pragma once
#include <string>

#include "imess/client/endpoint.hpp"

namespace imess::messjog {

struct JogOptions {
  client::Endpoint endpoint;
  bool wait = false;  // start even when messd is not running yet, and keep trying
  bool help = false;
};

// Throws client::UsageError naming the bad argument and what is accepted.
JogOptions parse_jog_options(int argc, const char* const argv[]);

std::string jog_usage();

}  // namespace imess::messjog
