// messcap: the CAD module's successor — captures N (or open-ended) measured points from messd,
// printing each and writing it to a .csv/.xyz file the moment it arrives.
#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>

#include "capture_options.hpp"
#include "imess/client/connect_error.hpp"
#include "imess/client/connection.hpp"
#include "imess/client/usage_error.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"
#include "point_file.hpp"

namespace {

volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void on_stop_signal(int) { g_stop_signal = 1; }

void install_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;  // no SA_RESTART: poll() returns EINTR at once
  sigemptyset(&sa.sa_mask);
  for (int s : {SIGINT, SIGTERM}) sigaction(s, &sa, nullptr);
}

}  // namespace

int main(int argc, char* argv[]) {
  using namespace imess;
  messcap::CaptureOptions options;
  try {
    options = messcap::parse_capture_options(argc, argv);
  } catch (const client::UsageError& e) {
    std::cerr << "messcap: " << e.what() << "\n(try messcap --help)\n";
    return client::kExitUsage;
  }
  if (options.help) {
    std::cout << messcap::capture_usage();
    return client::kExitOk;
  }

  std::unique_ptr<messcap::PointFile> file;
  try {
    if (options.output) file = std::make_unique<messcap::PointFile>(*options.output, options.mode);
  } catch (const std::exception& e) {
    std::cerr << "messcap: " << e.what() << "\n";
    return client::kExitFailure;
  }
  std::optional<client::Connection> link;
  try {
    link.emplace(client::Connection::open(options.endpoint));
  } catch (const client::ConnectError& e) {
    if (file) file->discard_if_unused();
    std::cerr << "messcap: " << e.what() << "\n";
    return client::kExitFailure;
  }
  install_signal_handlers();
  link->send_line("Hello messcap");
  std::cerr << "messcap: connected to " << options.endpoint.to_string() << "; "
            << (options.count ? "waiting for " + std::to_string(*options.count) + " points"
                              : std::string("capturing until Ctrl-C or messd closes the connection"))
            << "\n";

  int received = 0;
  auto done = [&] { return options.count && received >= *options.count; };
  auto on_line = [&](std::string_view line) {
    if (done()) return;  // N reached: later points in the same read are not ours to take
    auto message = protocol::parse_message(line);
    auto* point = std::get_if<protocol::MeasPtMsg>(&message);
    if (!point) return;
    ++received;
    if (file) file->append(point->p);  // to disk first: the screen can wait
    std::string text = "point " + std::to_string(received) + ":";
    for (double v : {point->p.x, point->p.y, point->p.z}) {
      text.push_back(' ');
      protocol::append_mm(text, v);
    }
    std::printf("%s\n", text.c_str());
    std::fflush(stdout);
  };

  std::string ended_by;
  try {
    while (!done()) {
      if (g_stop_signal) {
        ended_by = "interrupted";
        break;
      }
      auto status = link->poll_lines(std::chrono::milliseconds{200}, on_line);
      if (status == client::ReadStatus::Closed) {
        ended_by = "connection " + link->close_reason();
        break;
      }
    }
  } catch (const std::exception& e) {  // a write error: the points so far are on disk
    std::cerr << "messcap: " << e.what() << " (after " << received << " points)\n";
    return client::kExitFailure;
  }

  link->finish();
  std::cerr << "messcap: " << received << (received == 1 ? " point" : " points");
  if (file) std::cerr << " written to " << file->path();
  if (!ended_by.empty()) std::cerr << " (" << ended_by << ")";
  std::cerr << "\n";
  if (options.count && received < *options.count) {
    std::cerr << "messcap: stopped before all " << *options.count << " points arrived\n";
    return client::kExitIncomplete;
  }
  return client::kExitOk;
}
