// The capture loop: connect, say Hello, take MeasPt until N points, Ctrl-C or the link closes;
// then the optional fit. The file is written before the screen: the screen can wait.
#include "capture_command.hpp"

#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>

#include "capture_options.hpp"
#include "fit_message.hpp"
#include "frame_option.hpp"
#include "imess/client/stop_signal.hpp"
#include "imess/client/connect_error.hpp"
#include "imess/client/connection.hpp"
#include "imess/client/usage_error.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"
#include "point_file.hpp"

namespace imess::messcap {
int run_capture(int argc, const char* const argv[]) {
  CaptureOptions options;
  try {
    options = parse_capture_options(argc, argv);
  } catch (const client::UsageError& e) {
    std::cerr << "messcap: " << e.what() << "\n(try messcap --help)\n";
    return client::kExitUsage;
  }
  if (options.help) {
    std::cout << capture_usage();
    return client::kExitOk;
  }

  std::optional<metrology::Frame> frame;
  std::unique_ptr<PointFile> file;
  try {
    if (options.out.frame) frame = load_named_frame(*options.out.frames_file, *options.out.frame);
    exchange::ExportData base;
    base.frame = options.out.frame.value_or("");
    base.outer = options.out.outer;
    if (options.out.output) file = std::make_unique<PointFile>(*options.out.output, options.out.mode, base);
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
  client::install_stop_signals({SIGINT, SIGTERM});
  link->send_line("Hello messcap");
  std::cerr << "messcap: connected to " << options.endpoint.to_string() << "; "
            << (options.count ? "waiting for " + std::to_string(*options.count) + " points"
                              : std::string("capturing until Ctrl-C or messd closes the connection"))
            << (frame ? "; points in frame " + *options.out.frame : std::string()) << "\n";

  int received = 0;
  std::vector<Eigen::Vector3d> kept;  // for --fit
  auto done = [&] { return options.count && received >= *options.count; };
  auto on_line = [&](std::string_view line) {
    if (done()) return;  // N reached: later points in the same read are not ours to take
    auto message = protocol::parse_message(line);
    auto* point = std::get_if<protocol::MeasPtMsg>(&message);
    if (!point) return;
    ++received;
    Eigen::Vector3d p(point->p.x, point->p.y, point->p.z);
    if (frame) p = frame->point_from_parent(p);
    if (file) file->append(p);  // to disk first
    if (options.out.fit) kept.push_back(p);
    std::string text = "point " + std::to_string(received) + ":";
    for (double v : {p.x(), p.y(), p.z()}) {
      text.push_back(' ');
      protocol::append_mm(text, v);
    }
    std::printf("%s\n", text.c_str());
    std::fflush(stdout);
  };

  std::string ended_by;
  try {
    while (!done()) {
      if (client::stop_requested()) {
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

  bool fit_failed = false;
  if (options.out.fit) {
    auto fit = exchange::fit_points(*options.out.fit, kept);
    if (fit) {
      std::printf("%s\n", exchange::to_json(*fit).c_str());
      std::fflush(stdout);
      try {
        if (file) file->set_fit(*fit);
      } catch (const std::exception& e) {
        std::cerr << "messcap: " << e.what() << "\n";
        return client::kExitFailure;
      }
    } else {
      std::cerr << "messcap: " << fit_failure_message(*options.out.fit, kept.size(), "this capture", fit.error())
                << (file ? " (the points are in " + file->path() + ")" : std::string()) << "\n";
      fit_failed = true;
    }
  }
  if (options.count && received < *options.count) {
    std::cerr << "messcap: stopped before all " << *options.count << " points arrived\n";
    return client::kExitIncomplete;
  }
  return fit_failed ? client::kExitFailure : client::kExitOk;
}

}  // namespace imess::messcap
