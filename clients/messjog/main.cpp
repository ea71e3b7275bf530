// messjog: the IMESS jog panel in a terminal (the 1996 QUICKMESS). Keys in, StartMv/StopMv/
// ForcePt out, live positions on screen; reconnects by itself when messd restarts.
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "imess/client/stop_signal.hpp"
#include "imess/client/connect_error.hpp"
#include "imess/client/connection.hpp"
#include "imess/client/usage_error.hpp"
#include "jog_options.hpp"
#include "jog_screen.hpp"
#include "jog_session.hpp"
#include "key_map.hpp"

int main(int argc, char* argv[]) {
  using namespace imess;
  messjog::JogOptions options;
  try {
    options = messjog::parse_jog_options(argc, argv);
  } catch (const client::UsageError& e) {
    std::cerr << "messjog: " << e.what() << "\n(try messjog --help)\n";
    return client::kExitUsage;
  }
  if (options.help) {
    std::cout << messjog::jog_usage();
    return client::kExitOk;
  }

  messjog::JogSession session(options.endpoint, client::Reconnector::Options{});
  try {
    session.adopt(client::Connection::open(options.endpoint));
  } catch (const client::ConnectError& e) {
    if (!options.wait || e.kind() == client::ConnectError::Kind::NotResolved) {
      std::cerr << "messjog: " << e.what() << "\n";
      return client::kExitFailure;
    }
  }
  if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
    std::cerr << "messjog: needs a terminal (stdin and stdout must be a tty)\n";
    return client::kExitFailure;
  }

  client::install_stop_signals({SIGTERM, SIGHUP, SIGINT});
  messjog::JogScreen screen;
  while (!session.panel().quit_requested()) {
    if (client::stop_requested()) {
      session.act(messjog::JogAction::Quit);
      break;
    }
    screen.draw(session);  // curses sends only what changed
    pollfd fds[2] = {{STDIN_FILENO, POLLIN, 0}, {session.fd(), POLLIN, 0}};
    auto wait = std::min(session.max_wait(), std::chrono::milliseconds{1000});
    ::poll(fds, session.fd() >= 0 ? 2 : 1, static_cast<int>(wait.count()));
    for (int key; (key = screen.read_key()) != -1;) session.act(messjog::action_for_key(key));
    session.service();
  }
  session.finish();
  return client::kExitOk;
}
