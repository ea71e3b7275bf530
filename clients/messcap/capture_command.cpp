// The capture loop: connect, say Hello, take Hit (or, from a messd without a journal, MeasPt)
// until N points, Ctrl-C or the link closes (--reconnect: until N or Ctrl-C, catching up with
// Replay after each reconnect); then the optional fit. The file is written before the screen.
#include "capture_command.hpp"

#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <thread>

#include "capture_options.hpp"
#include "fit_message.hpp"
#include "frame_option.hpp"
#include "imess/client/stop_signal.hpp"
#include "imess/client/connect_error.hpp"
#include "imess/client/connection.hpp"
#include "imess/client/reconnector.hpp"
#include "imess/client/usage_error.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"
#include "hit_numbers.hpp"
#include "hit_sequencer.hpp"
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
  // --append to a file that keeps hit numbers: continue after its last one, fetching the rest.
  std::optional<std::uint64_t> last_kept;
  try {
    if (file && options.out.mode == OpenMode::Append && keeps_hit_numbers(file->path()))
      last_kept = last_hit_number(file->path());
  } catch (const std::exception& e) {
    std::cerr << "messcap: " << e.what() << "\n";
    return client::kExitFailure;
  }
  HitSequencer sequencer(last_kept);
  bool hit_mode = false;  // a Hit line was seen: MeasPt lines are the same points again

  client::Reconnector link(options.endpoint, {std::chrono::milliseconds{500}, std::chrono::milliseconds{500}});
  try {
    link.adopt(client::Connection::open(options.endpoint));
  } catch (const client::ConnectError& e) {
    if (file) file->discard_if_unused();
    std::cerr << "messcap: " << e.what() << "\n";
    return client::kExitFailure;
  }
  client::install_stop_signals({SIGINT, SIGTERM});
  auto greet = [&] {
    link.send_line("Hello messcap");
    sequencer.on_connected();
  };
  greet();
  std::cerr << "messcap: connected to " << options.endpoint.to_string() << "; "
            << (options.count ? "waiting for " + std::to_string(*options.count) + " points"
                              : std::string("capturing until Ctrl-C") +
                                    (options.reconnect ? "" : " or until messd closes the connection"))
            << (frame ? "; points in frame " + *options.out.frame : std::string())
            << (last_kept ? "; continuing after hit " + std::to_string(*last_kept) : std::string()) << "\n";

  int received = 0;
  std::vector<Eigen::Vector3d> kept;  // for --fit
  auto done = [&] { return options.count && received >= *options.count; };
  auto take = [&](const protocol::Xyz& at, std::optional<std::uint64_t> seq) {
    if (done()) return;  // N reached: later points in the same read are not ours to take
    ++received;
    Eigen::Vector3d p(at.x, at.y, at.z);
    if (frame) p = frame->point_from_parent(p);
    if (file) file->append(p, seq);  // to disk first
    if (options.out.fit) kept.push_back(p);
    std::string text = "point " + std::to_string(received) + ":";
    for (double v : {p.x(), p.y(), p.z()}) {
      text.push_back(' ');
      protocol::append_mm(text, v);
    }
    std::printf("%s\n", text.c_str());
    std::fflush(stdout);
  };
  auto take_all = [&](const std::vector<protocol::HitMsg>& due) {
    for (const auto& h : due) take(h.p, h.seq);
  };
  auto on_line = [&](std::string_view line) {
    auto message = protocol::parse_message(line);
    if (auto* hit = std::get_if<protocol::HitMsg>(&message)) {
      hit_mode = true;
      take_all(sequencer.on_hit(*hit));
    } else if (auto* point = std::get_if<protocol::MeasPtMsg>(&message)) {
      if (!hit_mode) take(point->p, std::nullopt);  // a messd without a journal
    } else if (auto* ok = std::get_if<protocol::OkMsg>(&message); ok && ok->verb == "Replay") {
      auto count = ok->args.size() == 2 ? protocol::parse_sequence_number(ok->args[0]) : std::nullopt;
      auto newest = ok->args.size() == 2 ? protocol::parse_sequence_number(ok->args[1]) : std::nullopt;
      if (count && newest) {
        if (*count > 0) std::cerr << "messcap: Replay gave " << *count << " journaled hits (up to " << *newest << ")\n";
        take_all(sequencer.on_replay_ok(*count, *newest));
      }
    } else if (auto* err = std::get_if<protocol::ErrMsg>(&message)) {
      // messcap sends only Hello (never refused) and Replay: an Err answers a Replay.
      auto oldest = protocol::parse_sequence_number(std::string_view(err->text).substr(err->text.rfind(' ') + 1));
      if (err->code == static_cast<int>(protocol::ErrorCode::NotInJournal) && oldest) {
        take_all(sequencer.on_replay_gone(*oldest));
      } else {
        std::cerr << "messcap: messd refused Replay (" << line << "); points missed while away cannot be fetched\n";
        take_all(sequencer.on_replay_refused());
      }
    }
  };

  std::string ended_by;
  bool link_lost = false;
  try {
    while (!done()) {
      if (client::stop_requested()) {
        ended_by = "interrupted";
        break;
      }
      if (!link.connected()) {
        if (link.maintain()) {
          std::cerr << "messcap: reconnected to " << options.endpoint.to_string() << "\n";
          greet();
        } else {
          std::this_thread::sleep_for(std::min(std::chrono::milliseconds{200}, link.until_next_attempt()));
          continue;
        }
      }
      if (auto from = sequencer.take_replay_request()) link.send_line("Replay " + std::to_string(*from));
      auto status = link.connection() ? link.connection()->poll_lines(std::chrono::milliseconds{200}, on_line)
                                      : client::ReadStatus::Closed;
      for (const auto& note : sequencer.take_notes()) std::cerr << "messcap: " << note << "\n";
      if (status == client::ReadStatus::Closed) {
        link.lost();  // keeps the connection's close reason
        const std::string reason = link.last_error().empty() ? "lost" : link.last_error();
        if (!options.reconnect) {
          ended_by = "connection " + reason;
          link_lost = true;
          break;
        }
        std::cerr << "messcap: connection " << reason << "; reconnecting (Ctrl-C ends the capture)\n";
      }
    }
  } catch (const std::exception& e) {  // a write error: the points so far are on disk
    std::cerr << "messcap: " << e.what() << " (after " << received << " points)\n";
    return client::kExitFailure;
  }

  if (auto* c = link.connection()) c->finish();
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
  if (link_lost) {
    std::cerr << "messcap: messd went away before the capture was ended (start messcap with --reconnect to wait "
                 "for it)\n";
    return client::kExitLinkLost;
  }
  if (options.count && received < *options.count) {
    std::cerr << "messcap: stopped before all " << *options.count << " points arrived\n";
    return client::kExitIncomplete;
  }
  return fit_failed ? client::kExitFailure : client::kExitOk;
}

}  // namespace imess::messcap
