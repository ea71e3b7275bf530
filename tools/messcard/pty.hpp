// A pseudo-terminal for the card: the master side for messcard, the slave side reachable as a
// symbolic link (what messd opens as its serial device).
#pragma once
#include <string>

namespace imess::messcard {

struct Pty {
  int master = -1;  // non-blocking, raw
  int slave = -1;   // kept open by messcard, so the master never reads EIO while messd is away
  std::string slave_name;  // /dev/pts/N
};

// Creates the pseudo-terminal and points link at its slave (replacing an older link; refusing
// to replace anything that is not a symbolic link). Throws std::runtime_error naming the problem.
Pty open_pty(const std::string& link);

}  // namespace imess::messcard
