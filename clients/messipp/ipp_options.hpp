// messipp's command line.
#pragma once
#include <chrono>
#include <string>

#include "imess/client/endpoint.hpp"

namespace imess::messipp {

// messd's I++ DME port (server.ippdme_port, docs/configuration.md).
inline constexpr std::uint16_t kIppPort = 1294;

struct IppOptions {
  client::Endpoint endpoint{"127.0.0.1", kIppPort};
  bool raw = false;  // send lines without checking them first (to try the server's own errors)
  // Longest wait for an answer messipp needs before it goes on (the Ack before the next line, the
  // `%`s before closing); 0: no limit.
  std::chrono::milliseconds timeout{30000};
  bool help = false;
};

// Throws client::UsageError naming the bad argument and what is accepted.
IppOptions parse_ipp_options(int argc, const char* const argv[]);

std::string ipp_usage();

}  // namespace imess::messipp
