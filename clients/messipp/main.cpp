// messipp: I++ DME by hand — type method calls, messipp tags them and prints the server's lines.
#include <unistd.h>

#include <csignal>
#include <iostream>
#include <optional>

#include "imess/client/connect_error.hpp"
#include "imess/client/stop_signal.hpp"
#include "imess/client/usage_error.hpp"
#include "imess/ippdme/line_framer.hpp"
#include "ipp_options.hpp"
#include "ipp_session.hpp"

int main(int argc, char* argv[]) {
  using namespace imess;
  messipp::IppOptions options;
  try {
    options = messipp::parse_ipp_options(argc, argv);
  } catch (const client::UsageError& e) {
    std::cerr << "messipp: " << e.what() << "\n(try messipp --help)\n";
    return client::kExitUsage;
  }
  if (options.help) {
    std::cout << messipp::ipp_usage();
    return client::kExitOk;
  }

  std::optional<client::Connection> link;
  try {
    // I++ DME answers may be as long as the spec's lines (an EnumAllProp), not messd's 200.
    link.emplace(client::Connection::open(options.endpoint, client::kDefaultConnectTimeout, ippdme::kMaxLineLength));
  } catch (const client::ConnectError& e) {
    std::cerr << "messipp: " << e.what() << "\n";
    return client::kExitFailure;
  }
  client::install_stop_signals({SIGINT, SIGTERM});
  messipp::SessionStreams io;
  io.transcript = !::isatty(STDIN_FILENO);
  if (!io.transcript)
    std::cerr << "messipp: connected to " << options.endpoint.to_string()
              << " (I++ DME); type a method call, e.g. StartSession(); quit or Ctrl-D ends\n";
  return messipp::run_ipp_session(*link, options, io);
}
