// MesscardProcess: starts build/bin/messcard on a new pseudo-terminal in a temporary directory
// (the link "tty" there) and stops it; its stdout lines ("messcard: …") can be awaited.
#pragma once
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace imess::test {

class MesscardProcess {
 public:
  // dir: where the link goes (a fresh temporary directory when empty); args: extra options.
  explicit MesscardProcess(std::vector<std::string> args = {}, std::string config = "", std::string dir = "") {
    if (dir.empty()) {
      dir = (std::filesystem::temp_directory_path() / "imess-messcard-XXXXXX").string();
      if (!mkdtemp(dir.data())) throw std::runtime_error("mkdtemp failed");
      own_dir_ = dir;
    }
    tty_ = dir + "/tty";
    if (config.empty()) config = std::string(IMESS_SOURCE_DIR) + "/config/servo-card.json";
    std::vector<std::string> all{std::string(IMESS_BIN_DIR) + "/messcard", "--pty", tty_, "--config", config};
    all.insert(all.end(), args.begin(), args.end());
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe failed");
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      dup2(out[1], STDOUT_FILENO);
      close(out[0]);
      std::vector<char*> argv;
      for (auto& a : all) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(argv[0], argv.data());
      _exit(127);
    }
    close(out[1]);
    out_ = out[0];
    if (!until("messcard: card on", 10)) throw std::runtime_error("messcard did not start");
  }
  ~MesscardProcess() {
    stop(SIGKILL);
    if (out_ >= 0) close(out_);
    if (!own_dir_.empty()) {
      std::error_code ec;
      std::filesystem::remove_all(own_dir_, ec);
    }
  }
  MesscardProcess(const MesscardProcess&) = delete;
  MesscardProcess& operator=(const MesscardProcess&) = delete;

  const std::string& tty() const { return tty_; }
  const std::string& dir() const { return own_dir_; }
  // Sends signal and waits for the end (SIGKILL: the card gone at once; SIGTERM: the cable pulled).
  void stop(int signal = SIGTERM) {
    if (pid_ <= 0) return;
    kill(pid_, signal);
    int st = 0;
    waitpid(pid_, &st, 0);
    pid_ = -1;
  }
  void signal(int sig) { kill(pid_, sig); }
  // Reads stdout until a line containing text (kept in output()); false after timeout_s.
  bool until(const std::string& text, double timeout_s) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    for (;;) {
      const auto nl = buf_.find('\n', scanned_);
      if (nl != std::string::npos) {
        const std::string line = buf_.substr(scanned_, nl - scanned_);
        scanned_ = nl + 1;
        if (line.find(text) != std::string::npos) return true;
        continue;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0 || out_ < 0) return false;
      pollfd p{out_, POLLIN, 0};
      if (poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
      char tmp[4096];
      const auto n = read(out_, tmp, sizeof tmp);
      if (n <= 0) {
        close(out_);
        out_ = -1;
        continue;
      }
      buf_.append(tmp, static_cast<std::size_t>(n));
    }
  }
  const std::string& output() const { return buf_; }

 private:
  pid_t pid_ = -1;
  int out_ = -1;
  std::string tty_, own_dir_, buf_;
  std::size_t scanned_ = 0;
};

}  // namespace imess::test
