// The capture loop: connect, Hello, take Hit and Scan lines (or MeasPt from a messd without a
// journal) until N points, Ctrl-C or the link closes (--reconnect: Replay after each reconnect;
// hits messd cannot give are reported); the optional fit. The points of one read from the
// connection go to the file together (one fdatasync), then to the screen; .hits takes only
// Hit and Scan lines.
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
#include "imess/client/hello_caps.hpp"
#include "imess/client/reconnector.hpp"
#include "imess/client/usage_error.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"
#include "hit_numbers.hpp"
#include "hit_sequencer.hpp"
#include "point_file.hpp"

namespace imess::messcap {
namespace {

// Where the points go: the frame they are given in, the file, and for --append to a file that
// keeps hit numbers the last one it holds (the capture continues after it, fetching the rest).
struct CaptureOutput {
  std::optional<metrology::Frame> frame;
  std::unique_ptr<PointFile> file;
  std::optional<std::uint64_t> last_kept;
};

// Loads the frame, opens the file; false (having said why) when either fails.
bool open_output(const CaptureOptions& options, CaptureOutput& output) {
  try {
    if (options.out.frame) output.frame = load_named_frame(*options.out.frames_file, *options.out.frame);
    exchange::ExportData base;
    // .hits keeps the Hit line's resolution; the formats of plain points MeasPt's 3 decimals.
    if (options.out.output && exchange::export_format_for(*options.out.output).needs_approach())
      base.decimals = exchange::kHitDecimals;
    base.frame = options.out.frame.value_or("");
    base.outer = options.out.outer;
    if (options.out.output) output.file = std::make_unique<PointFile>(*options.out.output, options.out.mode, base);
    if (output.file && !output.file->cut_line().empty())
      std::cerr << "messcap: cut the unfinished last line off " << output.file->path() << " ('"
                << output.file->cut_line() << "': a capture ended while writing it)\n";
  } catch (const std::exception& e) {
    std::cerr << "messcap: " << e.what() << "\n";
    return false;
  }
  try {
    if (output.file && options.out.mode == OpenMode::Append && keeps_hit_numbers(output.file->path()))
      output.last_kept = last_hit_number(output.file->path());
  } catch (const std::exception& e) {
    std::cerr << "messcap: " << e.what() << "\n";
    return false;
  }
  return true;
}

// One capture from connecting to the exit status.
class Capture {
 public:
  Capture(const CaptureOptions& options, CaptureOutput& output)
      : options_(options),
        output_(output),
        sequencer_(output.last_kept),
        link_(options.endpoint, {std::chrono::milliseconds{500}, std::chrono::milliseconds{500}}) {}

  int run() {
    if (!connect()) return client::kExitFailure;
    client::install_stop_signals({SIGINT, SIGTERM});
    greet();
    announce();
    try {
      receive_until_ended();
    } catch (const std::exception& e) {  // a write error: the points so far are on disk
      std::cerr << "messcap: " << e.what() << " (after " << received_ << " points)\n";
      return client::kExitFailure;
    }
    if (auto* c = link_.connection()) c->finish();
    if (refused_) {
      if (output_.file) output_.file->discard_if_unused();
      return client::kExitFailure;
    }
    report_received();
    const FitOutcome fit = options_.out.fit ? fit_kept() : FitOutcome::Done;
    if (fit == FitOutcome::NotWritten) return client::kExitFailure;
    return exit_status(fit == FitOutcome::NotFitted);
  }

 private:
  enum class FitOutcome { Done, NotFitted, NotWritten };

  bool connect() {
    try {
      link_.adopt(client::Connection::open(options_.endpoint));
      return true;
    } catch (const client::ConnectError& e) {
      if (output_.file) output_.file->discard_if_unused();
      std::cerr << "messcap: " << e.what() << "\n";
      return false;
    }
  }

  void greet() {
    link_.send_line("Hello messcap");
    sequencer_.on_connected();
  }

  void announce() const {
    std::cerr << "messcap: connected to " << options_.endpoint.to_string() << "; "
              << (options_.count ? "waiting for " + std::to_string(*options_.count) + " points"
                                 : std::string("capturing until Ctrl-C") +
                                       (options_.reconnect ? "" : " or until messd closes the connection"))
              << (output_.frame ? "; points in frame " + *options_.out.frame : std::string())
              << (output_.last_kept ? "; continuing after hit " + std::to_string(*output_.last_kept) : std::string())
              << "\n";
  }

  bool done() const { return refused_ || (options_.count && received_ >= *options_.count); }

  // The file holds hits with their approach and tip radius (.hits): only Hit and Scan lines can fill it.
  bool wants_approach() const { return output_.file && output_.file->needs_approach(); }

  // Reads lines until N points, Ctrl-C or (without --reconnect) the link closes; reconnects
  // and asks for the Replays the sequencer wants.
  void receive_until_ended() {
    while (!done()) {
      if (client::stop_requested()) {
        ended_by_ = "interrupted";
        return;
      }
      if (!link_.connected()) {
        if (!link_.maintain()) {
          std::this_thread::sleep_for(std::min(std::chrono::milliseconds{200}, link_.until_next_attempt()));
          continue;
        }
        std::cerr << "messcap: reconnected to " << options_.endpoint.to_string() << "\n";
        greet();
      }
      if (auto from = sequencer_.take_replay_request()) link_.send_line("Replay " + std::to_string(*from));
      auto status = link_.connection() ? link_.connection()->poll_lines(std::chrono::milliseconds{200},
                                                                        [this](std::string_view line) { on_line(line); })
                                       : client::ReadStatus::Closed;
      flush_taken();
      for (const auto& note : sequencer_.take_notes()) std::cerr << "messcap: " << note << "\n";
      if (status == client::ReadStatus::Closed && !on_closed()) return;
    }
  }

  // The link closed: false when that ends the capture (no --reconnect).
  bool on_closed() {
    link_.lost();  // keeps the connection's close reason
    const std::string reason = link_.last_error().empty() ? "lost" : link_.last_error();
    if (!options_.reconnect) {
      ended_by_ = "connection " + reason;
      link_lost_ = true;
      return false;
    }
    std::cerr << "messcap: connection " << reason << "; reconnecting (Ctrl-C ends the capture)\n";
    return true;
  }

  void on_line(std::string_view line) {
    auto message = protocol::parse_message(line);
    if (auto* hit = std::get_if<protocol::HitMsg>(&message)) {
      hit_mode_ = true;
      take_all(sequencer_.on_hit(*hit));
    } else if (auto* point = std::get_if<protocol::MeasPtMsg>(&message)) {
      if (hit_mode_) return;  // the point of the Hit just taken
      // A messd without a journal: its Hit, which messd sends right before, never came.
      if (wants_approach()) return refuse("sent a MeasPt point without a Hit before it (it keeps no hit journal)");
      take(to_vector(point->p), std::nullopt, std::nullopt);
    } else if (auto* ok = std::get_if<protocol::OkMsg>(&message)) {
      if (ok->verb == "Replay") on_replay_ok(*ok);
      if (ok->verb == "Hello" && wants_approach() && client::hello_lists_caps(ok->args) &&
          !client::hello_has_cap(ok->args, "journal"))
        refuse("sends only MeasPt points (its Hello lists no 'journal' among its Caps)");
    } else if (auto* err = std::get_if<protocol::ErrMsg>(&message)) {
      on_replay_err(*err, line);
    } else if (auto* data = std::get_if<protocol::DataMsg>(&message)) {
      // `Replay Lost first last`: journaled hits messd cannot give; the sequencer notes them.
      if (auto lost = data->verb == "Replay" ? protocol::parse_replay_lost(data->text) : std::nullopt)
        take_all(sequencer_.on_replay_lost(lost->first, lost->last));
    }
  }

  // `Ok Replay <count> <newest>`.
  void on_replay_ok(const protocol::OkMsg& ok) {
    auto count = ok.args.size() == 2 ? protocol::parse_sequence_number(ok.args[0]) : std::nullopt;
    auto newest = ok.args.size() == 2 ? protocol::parse_sequence_number(ok.args[1]) : std::nullopt;
    if (!count || !newest) return;
    if (*count > 0) std::cerr << "messcap: Replay gave " << *count << " journaled hits (up to " << *newest << ")\n";
    take_all(sequencer_.on_replay_ok(*count, *newest));
  }

  // messcap sends only Hello (never refused) and Replay: an Err answers a Replay.
  void on_replay_err(const protocol::ErrMsg& err, std::string_view line) {
    auto oldest = protocol::parse_sequence_number(std::string_view(err.text).substr(err.text.rfind(' ') + 1));
    if (err.code == static_cast<int>(protocol::ErrorCode::NotInJournal) && oldest) {
      take_all(sequencer_.on_replay_gone(*oldest));
    } else {
      std::cerr << "messcap: messd refused Replay (" << line << "); points missed while away cannot be fetched\n";
      take_all(sequencer_.on_replay_refused());
    }
  }

  // A .hits capture from a messd that sends no Hit: nothing is written, the capture ends.
  void refuse(const std::string& why) {
    if (refused_) return;
    refused_ = true;
    std::cerr << "messcap: cannot capture into " << output_.file->path()
              << ": a .hits file holds each hit's approach direction and tip radius, which only Hit lines carry, and "
                 "messd at "
              << options_.endpoint.to_string() << " " << why
              << ". Capture into .xyz or another format of plain points, or from a messd with a hit journal\n";
  }

  static Eigen::Vector3d to_vector(const protocol::Xyz& v) { return {v.x, v.y, v.z}; }

  void take_all(const std::vector<protocol::HitMsg>& due) {
    for (const auto& h : due) {
      metrology::ProbedPoint hit;
      hit.surface = to_vector(h.p);
      hit.approach = to_vector(h.dir);
      if (hit.has_approach()) hit.approach.normalize();  // 6 decimals on the wire
      hit.radius = h.radius;
      take(hit.surface, hit, PointNumber{h.seq, h.scan ? std::optional<std::uint64_t>(h.id) : std::nullopt});
    }
  }

  // One point (with the approach and tip radius of its hit when it came as a Hit or Scan line):
  // for the file and --fit; flush_taken() puts it on disk, then on the screen.
  void take(Eigen::Vector3d p, std::optional<metrology::ProbedPoint> hit, std::optional<PointNumber> number) {
    if (done()) return;  // N reached: later points in the same read are not ours to take
    ++received_;
    if (output_.frame) {
      p = output_.frame->point_from_parent(p);
      if (hit) hit = hit_from_parent(*output_.frame, *hit);
    }
    if (output_.file) hit ? output_.file->append(*hit, number) : output_.file->append(p, number);
    if (options_.out.fit) {
      kept_.push_back(p);
      if (hit) kept_hits_.push_back(*hit);
    }
    std::string text = "point " + std::to_string(received_) + ":";
    for (double v : {p.x(), p.y(), p.z()}) {
      text.push_back(' ');
      protocol::append_mm(text, v);
    }
    if (number) {  // its number for Align, Replay
      text += " (hit " + std::to_string(number->seq);
      text += number->scan ? " of scan " + std::to_string(*number->scan) + ")" : std::string(")");
    }
    screen_ += text + "\n";
  }

  // The points taken since the last call: into the file (synced), then on the screen.
  void flush_taken() {
    if (output_.file) output_.file->flush();
    if (screen_.empty()) return;
    std::fwrite(screen_.data(), 1, screen_.size(), stdout);
    std::fflush(stdout);
    screen_.clear();
  }

  void report_received() const {
    std::cerr << "messcap: " << received_ << (received_ == 1 ? " point" : " points");
    if (output_.file) std::cerr << " written to " << output_.file->path();
    if (!ended_by_.empty()) std::cerr << " (" << ended_by_ << ")";
    if (sequencer_.skipped() > 0)
      std::cerr << "; " << (sequencer_.skipped() == 1 ? "hit " : "hits ") << sequencer_.lost_text()
                << " missing: messd could not give " << (sequencer_.skipped() == 1 ? "it" : "them");
    std::cerr << "\n";
  }

  // --fit: the fit of the points taken, printed as JSON and written into the file; into a
  // .hits file probe-compensated, as `messcap fit` fits that file.
  FitOutcome fit_kept() {
    auto fit = wants_approach() ? exchange::fit_probed_points(*options_.out.fit, kept_hits_)
                                : exchange::fit_points(*options_.out.fit, kept_);
    if (!fit) {
      std::cerr << "messcap: " << fit_failure_message(*options_.out.fit, kept_.size(), "this capture", fit.error())
                << (output_.file ? " (the points are in " + output_.file->path() + ")" : std::string()) << "\n";
      return FitOutcome::NotFitted;
    }
    std::printf("%s\n", exchange::to_json(*fit).c_str());
    std::fflush(stdout);
    try {
      if (output_.file) output_.file->set_fit(*fit);
    } catch (const std::exception& e) {
      std::cerr << "messcap: " << e.what() << "\n";
      return FitOutcome::NotWritten;
    }
    return FitOutcome::Done;
  }

  int exit_status(bool fit_failed) const {
    if (link_lost_) {
      std::cerr << "messcap: messd went away before the capture was ended (start messcap with --reconnect to wait "
                   "for it)\n";
      return client::kExitLinkLost;
    }
    if (options_.count && received_ < *options_.count) {
      std::cerr << "messcap: stopped before all " << *options_.count << " points arrived\n";
      return client::kExitIncomplete;
    }
    return fit_failed ? client::kExitFailure : client::kExitOk;
  }

  const CaptureOptions& options_;
  CaptureOutput& output_;
  HitSequencer sequencer_;
  bool hit_mode_ = false;  // a Hit line was seen: MeasPt lines are the same points again
  client::Reconnector link_;
  int received_ = 0;
  std::string screen_;  // the taken points' lines, shown once they are on disk
  std::vector<Eigen::Vector3d> kept_;            // for --fit
  std::vector<metrology::ProbedPoint> kept_hits_;  // for --fit into .hits (all points came as Hit)
  bool refused_ = false;  // a .hits capture from a messd without Hit
  std::string ended_by_;
  bool link_lost_ = false;
};

}  // namespace

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
  CaptureOutput output;
  if (!open_output(options, output)) return client::kExitFailure;
  return Capture(options, output).run();
}

}  // namespace imess::messcap
