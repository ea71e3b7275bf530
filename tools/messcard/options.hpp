// messcard's command line: where the card sits (a new pseudo-terminal or an existing tty), the
// configuration whose "sim" section is the machine, and the faults to inject.
#pragma once
#include <optional>
#include <string>

namespace imess::messcard {

struct Options {
  std::string pty;      // --pty PATH: a new pseudo-terminal, PATH a symbolic link to its slave side
  std::string device;   // --device TTY: serve an existing tty instead
  std::string config;   // --config FILE
  std::optional<int> baud;
  double drop = 0, corrupt = 0;  // per byte, both directions
  double faults_at_ms = 0;       // … from this long after the host started the stream (0: from the start)
  double stall_ms = 0;           // the card stops answering this long, once
  double stall_at_ms = 1000;     // … this long after the host started the stream (or on SIGUSR1)
  unsigned seed = 1;
  bool realtime = true;  // ask for SCHED_FIFO (--no-rt: not)
  bool help = false;
};

// Throws std::invalid_argument saying what was wrong and what is accepted.
Options parse_options(int argc, char** argv);
const char* usage_text();

}  // namespace imess::messcard
