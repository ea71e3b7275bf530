// messmon: prints every line messd sends, time-stamped, as text or JSON lines.
#include <poll.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "imess/client/stop_signal.hpp"
#include "imess/client/connect_error.hpp"
#include "imess/client/reconnector.hpp"
#include "imess/client/usage_error.hpp"
#include "iso_time.hpp"
#include "monitor_line.hpp"
#include "monitor_options.hpp"

int main(int argc, char* argv[]) {
  using namespace imess;
  messmon::MonitorOptions options;
  try {
    options = messmon::parse_monitor_options(argc, argv);
  } catch (const client::UsageError& e) {
    std::cerr << "messmon: " << e.what() << "\n(try messmon --help)\n";
    return client::kExitUsage;
  }
  if (options.help) {
    std::cout << messmon::monitor_usage();
    return client::kExitOk;
  }

  client::Reconnector link(options.endpoint);
  try {
    link.adopt(client::Connection::open(options.endpoint));
  } catch (const client::ConnectError& e) {
    std::cerr << "messmon: " << e.what() << "\n";
    return client::kExitFailure;
  }
  client::install_stop_signals({SIGINT, SIGTERM});
  std::cerr << "messmon: connected to " << options.endpoint.to_string() << "\n";
  link.send_line("Hello messmon");

  auto print = [&](std::string_view line) {
    auto time = messmon::iso_local_time(std::chrono::system_clock::now());
    auto out = options.json ? messmon::json_line(time, line) : messmon::text_line(time, line);
    std::fwrite(out.data(), 1, out.size(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);  // live through pipes and into files
  };

  while (!client::stop_requested()) {
    if (auto* c = link.connection()) {
      if (c->poll_lines(std::chrono::milliseconds{500}, print) != client::ReadStatus::Closed) continue;
      std::cerr << "messmon: " << options.endpoint.to_string() << ": " << c->close_reason() << "\n";
      if (!options.reconnect) return client::kExitOk;
      link.lost();
      std::cerr << "messmon: reconnecting to " << options.endpoint.to_string() << " every second\n";
    }
    auto wait = std::min(link.until_next_attempt(), std::chrono::milliseconds{500});
    if (wait.count() > 0) ::poll(nullptr, 0, static_cast<int>(wait.count()));
    if (link.maintain()) {
      std::cerr << "messmon: reconnected to " << options.endpoint.to_string() << "\n";
      link.send_line("Hello messmon");
    }
  }
  if (auto* c = link.connection()) c->finish();
  return client::kExitOk;
}
