// messprog run: one poll() loop over the connection and, while a question is open, stdin;
// RunSession decides what to send and print, this file does the I/O.
#include "run_command.hpp"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <deque>
#include <iostream>

#include "imess/client/connect_error.hpp"
#include "imess/client/connection.hpp"
#include "interrupts.hpp"
#include "program_file.hpp"
#include "progress_view.hpp"
#include "run_session.hpp"
#include "upload.hpp"

namespace imess::messprog {
namespace {

using Clock = std::chrono::steady_clock;
// A silent controller is dropped by messd after control.idle_drop_s (300 s); a blank line,
// which gets no reply, keeps it.
constexpr auto kKeepAlive = std::chrono::seconds(30);
constexpr std::size_t kSendChunk = 64 * 1024;

class RunLoop {
 public:
  RunLoop(client::Connection connection, RunSession session, bool terminal_out)
      : conn_(std::move(connection)), session_(std::move(session)), progress_(terminal_out) {}

  // The whole conversation; the exit status. The link is ended cleanly (finish) in any case.
  int run() {
    const int status = converse();
    conn_.finish();
    return status;
  }

 private:
  int converse();
  std::optional<int> apply(RunOutput out);
  bool send(const std::vector<std::string>& lines);
  void drain() {
    conn_.receive([&](std::string_view l) { pending_.emplace_back(l); });
  }
  std::optional<int> read_answer();
  void write_out(const std::string& s) {
    if (s.empty()) return;
    std::cout << s << std::flush;
  }

  client::Connection conn_;
  RunSession session_;
  ProgressView progress_;
  std::deque<std::string> pending_;
  std::string answer_;
  bool stdin_open_ = true;
  Clock::time_point last_sent_ = Clock::now();
};

bool RunLoop::send(const std::vector<std::string>& lines) {
  std::string chunk;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    chunk += lines[i];
    chunk += '\n';  // every line ends here, so a blank last line of a chunk is sent too
    if (chunk.size() < kSendChunk && i + 1 < lines.size()) continue;
    if (!conn_.send_line(chunk)) return false;  // sent as it is: it ends in '\n'
    chunk.clear();
    drain();  // what messd says meanwhile waits in pending_, so it never blocks on us
    if (!conn_.is_open()) return false;
  }
  last_sent_ = Clock::now();
  return true;
}

std::optional<int> RunLoop::apply(RunOutput out) {
  if (out.end) write_out(progress_.done(out.end->outcome == ProgEndEvent::Outcome::Ok));
  if (!out.notes.empty() || !out.errors.empty() || out.ask) write_out(progress_.clear());
  for (const auto& n : out.notes) std::cout << n << "\n";
  std::cout << std::flush;
  for (const auto& e : out.errors) std::cerr << e << "\n";
  std::cerr << std::flush;
  if (out.ask) {
    std::cout << "messprog: abort or resume? [a/r] " << std::flush;
  } else if (!session_.asking() && !out.exit) {
    if (out.block) write_out(progress_.update(*out.block));
    else if (!out.notes.empty() || !out.errors.empty()) write_out(progress_.redraw());
  }
  if (!out.send.empty() && !send(out.send)) {
    if (!out.exit) return apply(session_.lost(conn_.close_reason()));
  }
  return out.exit;
}

std::optional<int> RunLoop::read_answer() {
  char buf[256];
  const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
  if (n < 0 && (errno == EINTR || errno == EAGAIN)) return std::nullopt;
  if (n <= 0) {
    stdin_open_ = false;
    std::cout << "\n";
    return apply(session_.answer("a"));  // end of input: nobody can resume, so abort
  }
  answer_.append(buf, static_cast<std::size_t>(n));
  for (auto nl = answer_.find('\n'); nl != std::string::npos; nl = answer_.find('\n')) {
    const std::string line = answer_.substr(0, nl);
    answer_.erase(0, nl + 1);
    if (auto e = apply(session_.answer(line))) return e;
  }
  return std::nullopt;
}

int RunLoop::converse() {
  install_interrupts();
  bool terminate_handled = false;
  if (auto e = apply(session_.start())) return *e;
  for (;;) {
    for (int n = take_interrupts(); n > 0; --n)
      if (auto e = apply(session_.interrupt())) return *e;
    if (terminate_requested() && !terminate_handled) {
      terminate_handled = true;
      if (auto e = apply(session_.terminate())) return *e;
    }
    while (!pending_.empty()) {
      const std::string line = std::move(pending_.front());
      pending_.pop_front();
      if (auto e = apply(session_.on_line(line))) return *e;
    }
    if (!conn_.is_open()) {
      if (auto e = apply(session_.lost(conn_.close_reason()))) return *e;
    }
    const auto now = Clock::now();
    if (session_.holds_control() && now - last_sent_ >= kKeepAlive && !send({""}))
      if (auto e = apply(session_.lost(conn_.close_reason()))) return *e;

    pollfd fds[2] = {{conn_.fd(), POLLIN, 0}, {STDIN_FILENO, POLLIN, 0}};
    const nfds_t count = session_.asking() && stdin_open_ ? 2 : 1;
    const auto until_keepalive = std::chrono::duration_cast<std::chrono::milliseconds>(last_sent_ + kKeepAlive - now);
    const int timeout = static_cast<int>(std::clamp<long long>(until_keepalive.count(), 0, 1000));
    const int ready = ::poll(fds, count, timeout);
    if (ready < 0) continue;  // EINTR: a signal; the top of the loop handles it
    if (fds[0].revents != 0 && conn_.receive([&](std::string_view l) { pending_.emplace_back(l); }) ==
                                   client::ReadStatus::Closed) {
      continue;  // handle what arrived before the end first; is_open() reports the loss next
    }
    if (count == 2 && fds[1].revents != 0)
      if (auto e = read_answer()) return *e;
  }
}

}  // namespace

int run_run_command(const ProgOptions& options) {
  Upload upload;
  try {
    upload = prepare_upload(options.file, read_program(options.file), options.lang);
  } catch (const std::runtime_error& e) {  // FileError, UploadError
    std::cerr << "messprog: " << e.what() << "\n";
    return 1;
  }
  std::optional<client::Connection> conn;
  try {
    conn.emplace(client::Connection::open(options.endpoint));
  } catch (const client::ConnectError& e) {
    std::cerr << "messprog: " << e.what() << "\n";
    return 1;
  }
  RunSession session(std::move(upload), {options.file, options.endpoint.to_string(), options.detached,
                                         ::isatty(STDIN_FILENO) == 1});
  RunLoop loop(std::move(*conn), std::move(session), ::isatty(STDOUT_FILENO) == 1);
  return loop.run();
}

}  // namespace imess::messprog
