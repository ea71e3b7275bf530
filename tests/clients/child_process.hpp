// ChildProcess: runs a built client executable for a test, stdout and stderr into temporary
// files (no pipe can fill up), with a deadline; killed if still running when destroyed.
#pragma once
#include <chrono>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace imess::test {

using namespace std::chrono_literals;

class ChildProcess {
 public:
  // stdin is `stdin_path` (a file of typed lines for messipp), /dev/null unless given.
  explicit ChildProcess(std::vector<std::string> argv, const std::string& stdin_path = "/dev/null");
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  void signal(int sig);
  // Exit status (128 + signal when killed by one), or nothing when it did not end in time.
  std::optional<int> wait(std::chrono::milliseconds timeout = 5s);
  // Waits until stdout contains `text`; false after the timeout or when the process ended without it.
  bool wait_for_output(const std::string& text, std::chrono::milliseconds timeout = 5s);

  std::string out() const;
  std::string err() const;

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
  std::string out_path_, err_path_;
};

struct RunResult {
  int status;
  std::string out, err;
};

// Runs to completion (fails the calling test if it takes longer than the timeout).
RunResult run_program(std::vector<std::string> argv, std::chrono::milliseconds timeout = 5s,
                      const std::string& stdin_path = "/dev/null");

// The path of a built client executable (IMESS_BIN_DIR/name).
std::string client_binary(const std::string& name);

// A fresh empty directory for a test's files, removed with everything in it at scope end.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

std::string read_file(const std::string& path);
bool file_exists(const std::string& path);

}  // namespace imess::test
