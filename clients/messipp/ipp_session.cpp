// messipp's loop. Input is read only while nothing typed waits to go out, so a pipe is read as
// the session goes and a terminal keeps what is typed ahead.
#include "ipp_session.hpp"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <deque>
#include <string>

#include "imess/client/stop_signal.hpp"
#include "imess/client/usage_error.hpp"
#include "imess/ippdme/format.hpp"
#include "tagger.hpp"
#include "transactions.hpp"
#include "typed_line.hpp"

namespace imess::messipp {
namespace {

using Clock = std::chrono::steady_clock;

void print_line(std::FILE* f, std::string_view prefix, std::string_view text) {
  std::fwrite(prefix.data(), 1, prefix.size(), f);
  std::fwrite(text.data(), 1, text.size(), f);
  std::fputc('\n', f);
  std::fflush(f);  // live through pipes and into files, in order with the other stream
}

std::string joined(const std::vector<std::string>& tags) {
  std::string s;
  for (const auto& t : tags) s += (s.empty() ? "" : ", ") + t;
  return s;
}

std::string seconds_text(std::chrono::milliseconds ms) {
  if (ms.count() % 1000 == 0) return std::to_string(ms.count() / 1000) + " s";
  return std::to_string(ms.count()) + " ms";
}

// Splits what stdin gave into lines; a CR before the LF (a file written on Windows) goes too.
class InputLines {
 public:
  void feed(std::string_view bytes, std::deque<std::string>& lines) {
    for (char c : bytes) {
      if (c != '\n') {
        partial_.push_back(c);
        continue;
      }
      if (!partial_.empty() && partial_.back() == '\r') partial_.pop_back();
      lines.push_back(std::move(partial_));
      partial_.clear();
    }
  }
  void end(std::deque<std::string>& lines) {  // a last line without its LF still counts
    if (!partial_.empty()) feed("\n", lines);
  }

 private:
  std::string partial_;
};

class Session {
 public:
  Session(client::Connection& link, const IppOptions& options, const SessionStreams& io)
      : link_(link), options_(options), io_(io) {}

  int run() {
    for (;;) {
      if (client::stop_requested()) return interrupted();
      send_what_may_go();
      if (failed_) return end(client::kExitFailure);
      const bool closing = (quit_ || input_ended_) && typed_.empty();
      if (closing && tx_.all_complete()) return finished();
      // messipp waits for the server only while a line is held back or the end waits for `%`s.
      const bool waiting = closing || !typed_.empty();
      if (waiting && options_.timeout.count() > 0 && Clock::now() - last_progress_ >= options_.timeout)
        return timed_out();
      if (!wait_for_input(waiting)) return end(client::kExitFailure);
    }
  }

 private:
  // The typed lines at the front, as far as the rules let them go: the previous line's Ack
  // first (IPPDME.md §3), and in a transcript a command-tag line only once everything before it
  // is complete, so the answers stand under their command. Event-tag lines need the Ack alone,
  // so a piped AbortE still stops the GoTo before it. A refused line keeps its place in the
  // order too: its message stands where the server's answer would have.
  void send_what_may_go() {
    const auto is_open = [this](ippdme::Tag t) { return tx_.is_open(ippdme::tag_text(t)); };
    while (!typed_.empty() && !quit_ && !failed_) {
      const TypedLine t = read_typed_line(typed_.front(), tagger_, is_open, options_.raw);
      if (t.action == LineAction::Ignore) {
        typed_.pop_front();
        continue;
      }
      if (t.action == LineAction::Quit) {
        quit_ = true;
        typed_.clear();
        return;
      }
      if (!tx_.last_answered()) return;
      if (io_.transcript && t.kind == ippdme::TagKind::Command && !tx_.all_complete()) return;
      typed_.pop_front();
      if (t.action == LineAction::Refuse) {
        ++refused_;
        print_line(io_.out, "messipp: not sent: ", t.text + " — " + t.error);
        continue;
      }
      if (!link_.send_line(t.text + std::string(ippdme::kLineEnd))) {
        lost();
        return;
      }
      if (io_.transcript) print_line(io_.out, "> ", t.text);
      tx_.sent(std::string_view(t.text).substr(0, ippdme::kTagLength));
      if (t.tag && t.typed_tag)
        tagger_.sent_typed(*t.tag);
      else if (t.tag)
        tagger_.sent(*t.tag);
      last_progress_ = Clock::now();
    }
  }

  // One poll() on the socket and, while nothing typed waits, stdin. False when the link ended.
  bool wait_for_input(bool waiting) {
    const bool read_stdin = typed_.empty() && !input_ended_ && !quit_;
    pollfd fds[2] = {{link_.fd(), POLLIN, 0}, {read_stdin ? io_.in : -1, POLLIN, 0}};
    int timeout_ms = 500;  // the stop flag and the timeout are looked at this often at least
    if (waiting && options_.timeout.count() > 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          options_.timeout - (Clock::now() - last_progress_));
      timeout_ms = static_cast<int>(std::clamp<long long>(left.count() + 1, 0, timeout_ms));
    }
    const int n = ::poll(fds, 2, timeout_ms);
    if (n < 0) return true;  // EINTR: the loop looks at the stop flag
    if (fds[0].revents != 0) {
      const auto status = link_.receive([this](std::string_view line) {
        print_line(io_.out, "", line);
        if (tx_.received(line)) last_progress_ = Clock::now();
      });
      if (status == client::ReadStatus::Closed) {
        lost();
        return false;
      }
    }
    if (fds[1].revents != 0) read_stdin_once();
    return true;
  }

  void read_stdin_once() {
    char buf[4096];
    const ssize_t n = ::read(io_.in, buf, sizeof buf);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) return;
    if (n <= 0) {  // the end of input (Ctrl-D), or stdin gone: the same for the session
      input_ended_ = true;
      input_.end(typed_);
      return;
    }
    input_.feed(std::string_view(buf, static_cast<std::size_t>(n)), typed_);
  }

  void lost() {
    std::string why = "messipp: " + link_.endpoint().to_string() + ": " + link_.close_reason();
    if (!tx_.all_complete()) why += "; no end yet to " + joined(tx_.open_tags());
    print_line(io_.err, "", why);
    failed_ = true;
  }

  int timed_out() {
    const bool held = !tx_.last_answered();
    print_line(io_.err, "",
               "messipp: no answer from " + link_.endpoint().to_string() + " for " + seconds_text(options_.timeout) +
                   (tx_.all_complete() ? std::string() : "; still open: " + joined(tx_.open_tags())) +
                   (held ? " (no Ack yet)" : "") + " — giving up (--timeout S waits longer, 0 as long as it takes)");
    return end(client::kExitFailure);
  }

  int interrupted() {
    if (tx_.all_complete() && typed_.empty()) return end(client::kExitOk);
    print_line(io_.err, "",
               "messipp: interrupted" +
                   (tx_.all_complete() ? std::string() : "; no end yet to " + joined(tx_.open_tags())));
    return end(client::kExitFailure);
  }

  // The input ended and everything sent is complete: ok, unless a piped line was held back (a
  // script that did not run as written; a person at the terminal saw the refusal at once).
  int finished() {
    if (refused_ == 0 || !io_.transcript) return end(client::kExitOk);
    print_line(io_.err, "", "messipp: " + std::to_string(refused_) + (refused_ == 1 ? " line was" : " lines were") +
                                " refused and not sent");
    return end(client::kExitFailure);
  }

  int end(int status) {
    if (link_.is_open()) link_.finish();
    return status;
  }

  client::Connection& link_;
  const IppOptions& options_;
  SessionStreams io_;
  Tagger tagger_;
  Transactions tx_;
  InputLines input_;
  std::deque<std::string> typed_;  // lines read and not yet handled, in order
  bool input_ended_ = false, quit_ = false, failed_ = false;
  int refused_ = 0;
  Clock::time_point last_progress_ = Clock::now();
};

}  // namespace

int run_ipp_session(client::Connection& link, const IppOptions& options, const SessionStreams& io) {
  return Session(link, options, io).run();
}

}  // namespace imess::messipp
