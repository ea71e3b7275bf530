// The servers the benchmark talks to: messd or bench_echo started here as child processes
// (output to a log file in a temporary directory, the port read from their "OK, listening
// on 127.0.0.1:PORT" line), or a messd someone else started (--port, --pid).
#pragma once
#include <string>
#include <vector>

#include "temp_dir.hpp"

namespace imess::bench {

class ServerProcess {
 public:
  // Starts `path` with `args`, stdout and stderr to `log_path`; returns once it printed
  // "... OK, listening on 127.0.0.1:PORT". Throws std::runtime_error with the log's tail when
  // it exits or says nothing of the kind within timeout_s.
  ServerProcess(const std::string& path, const std::vector<std::string>& args, std::string log_path, double timeout_s = 15);
  // One already running: port (and pid, 0 when unknown: no CPU or memory figures).
  ServerProcess(int port, int pid);
  ~ServerProcess();  // a child: SIGTERM, then waits (SIGKILL after 5 s)
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  int port() const { return port_; }
  int pid() const { return pid_; }
  bool child() const { return child_; }
  bool running() const;
  std::string log_tail(std::size_t bytes = 2000) const;
  // Stops a child now (nothing for one that is not ours); its exit status (-1: not ours).
  int stop();

 private:
  int port_ = 0, pid_ = 0, status_ = -1;
  bool child_ = false;
  std::string log_path_;
};

// The directory this program was started from (/proc/self/exe's), where the build puts
// messd and bench_echo beside bench_net.
std::string own_bin_dir();

}  // namespace imess::bench
