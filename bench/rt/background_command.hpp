// BackgroundCommand: a shell command (the load generator of the loaded run) started in a
// process group of its own, its output kept in a file, stopped with the whole group.
#pragma once
#include <sys/types.h>

#include <optional>
#include <string>

namespace imess::bench {

class BackgroundCommand {
 public:
  // Starts `/bin/sh -c command`, stdout and stderr into `log_path`.
  BackgroundCommand(const std::string& command, std::string log_path);
  ~BackgroundCommand() { stop(); }
  BackgroundCommand(const BackgroundCommand&) = delete;
  BackgroundCommand& operator=(const BackgroundCommand&) = delete;

  // The exit status once it has ended by itself (128 + signal), none while it runs.
  std::optional<int> ended();
  // SIGTERM to its process group, SIGKILL after 2 s; returns how it had ended when it ended
  // before (none when it was still running and was stopped here).
  std::optional<int> stop();
  std::string log_tail(std::size_t max_chars = 400) const;

 private:
  pid_t pid_ = -1;
  std::optional<int> status_;
  std::string log_path_;
};

// `text` with every {name} replaced by value.
std::string substitute(std::string text, const std::string& name, const std::string& value);

}  // namespace imess::bench
