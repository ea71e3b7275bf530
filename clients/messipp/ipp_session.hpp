// The session loop of messipp: lines from stdin go out tagged, one Ack at a time; whatever the
// server sends is printed the moment it arrives; the end of input (or `quit`) ends the link once
// every line sent is complete. One poll() on stdin and the socket, as in the other clients.
#pragma once
#include <cstdio>

#include "imess/client/connection.hpp"
#include "ipp_options.hpp"

namespace imess::messipp {

struct SessionStreams {
  int in = 0;                  // lines typed or piped
  std::FILE* out = stdout;     // the server's lines (and, in a transcript, the lines sent)
  std::FILE* err = stderr;     // messipp's own notices
  bool transcript = false;     // stdin is not a terminal: echo "> " lines, complete before a command
};

// Runs until the input ends and every transaction is complete, the link ends, the timeout
// passes or a stop signal comes. Returns the exit status (docs/clients.md, "messipp").
int run_ipp_session(client::Connection& link, const IppOptions& options, const SessionStreams& io);

}  // namespace imess::messipp
