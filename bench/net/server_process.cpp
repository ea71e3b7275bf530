// Child servers: fork/exec with output to a log file, waiting for the listening line, SIGTERM.
#include "server_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "clock.hpp"

namespace imess::bench {

std::string own_bin_dir() {
  std::error_code ec;
  auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return ".";
  return exe.parent_path().string();
}

namespace {
std::string read_file(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// The port of the first "OK, listening on ADDRESS:PORT" line, 0 while there is none.
int listening_port(const std::string& log) {
  const auto at = log.find("OK, listening on ");
  if (at == std::string::npos) return 0;
  const auto eol = log.find('\n', at);
  if (eol == std::string::npos) return 0;  // the line is not complete yet
  const auto colon = log.rfind(':', eol);
  if (colon == std::string::npos || colon < at) return 0;
  return std::atoi(log.c_str() + colon + 1);
}
}  // namespace

ServerProcess::ServerProcess(const std::string& path, const std::vector<std::string>& args, std::string log_path, double timeout_s)
    : child_(true), log_path_(std::move(log_path)) {
  if (access(path.c_str(), X_OK) != 0)
    throw std::runtime_error("cannot run '" + path + "': " + std::strerror(errno) + " (build it, or name another with --messd/--echo)");
  const int log = ::open(log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log < 0) throw std::runtime_error("cannot write the log " + log_path_ + ": " + std::strerror(errno));
  std::vector<std::string> all{path};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid_ == 0) {
    // The server ends with bench_net however bench_net ends (a crash, Ctrl-C, a closed pipe):
    // no messd is left behind holding its port and temporary directory.
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);  // the parent is already gone
    dup2(log, STDOUT_FILENO);
    dup2(log, STDERR_FILENO);
    const int devnull = ::open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, STDIN_FILENO);
    execv(path.c_str(), argv.data());
    _exit(127);
  }
  ::close(log);
  const std::int64_t deadline = mono_ns() + static_cast<std::int64_t>(timeout_s * 1e9);
  while (mono_ns() < deadline) {
    port_ = listening_port(read_file(log_path_));
    if (port_ > 0) return;
    int st = 0;
    if (waitpid(pid_, &st, WNOHANG) == pid_) {
      pid_ = 0;
      throw std::runtime_error(path + " exited at start (status " + std::to_string(WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st)) +
                               "); its output:\n" + log_tail());
    }
    usleep(5000);
  }
  stop();
  throw std::runtime_error(path + " printed no 'OK, listening on' line within " + std::to_string(timeout_s) + " s; its output:\n" +
                           log_tail());
}

ServerProcess::ServerProcess(int port, int pid) : port_(port), pid_(pid) {}

ServerProcess::~ServerProcess() { stop(); }

bool ServerProcess::running() const {
  if (pid_ <= 0) return !child_;
  if (child_) return waitpid(pid_, nullptr, WNOHANG) == 0;
  return kill(pid_, 0) == 0;
}

std::string ServerProcess::log_tail(std::size_t bytes) const {
  if (log_path_.empty()) return {};
  std::string log = read_file(log_path_);
  return log.size() > bytes ? "..." + log.substr(log.size() - bytes) : log;
}

int ServerProcess::stop() {
  if (!child_ || pid_ <= 0) return status_;
  kill(pid_, SIGTERM);
  int st = 0;
  const std::int64_t deadline = mono_ns() + 5'000'000'000;
  pid_t r = 0;
  while ((r = waitpid(pid_, &st, WNOHANG)) == 0 && mono_ns() < deadline) usleep(10000);
  if (r == 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, &st, 0);
  }
  pid_ = 0;
  status_ = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return status_;
}

}  // namespace imess::bench
