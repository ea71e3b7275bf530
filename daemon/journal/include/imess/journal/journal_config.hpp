// Where the journal lives and how it trades disk writes against what a power cut may lose.
#pragma once
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace imess::journal {

struct JournalConfig {
  std::string dir;                                // created if missing; messd chooses a default
  std::chrono::milliseconds fsync_interval{100};  // fdatasync at the latest this long after a hit; 0: every hit
  std::uint64_t max_bytes = 4u << 20;             // per file; then a new file is begun
  std::size_t files = 8;                          // files kept; the oldest beyond are deleted
};

// The journal cannot be created, read or written; the text names the path and the cause.
class JournalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace imess::journal
