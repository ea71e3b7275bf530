// Start-up recovery: the last intact record of the newest journal file, and whatever torn or
// garbled bytes follow it (a crash mid-write, zeros after a power cut) to be cut off.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace imess::journal {

struct Tail {
  std::optional<std::uint64_t> last_seq;  // none: the file holds no intact record
  std::uint64_t good_bytes = 0;           // the file up to and including that record's "\n"
  std::uint64_t file_bytes = 0;
};

// Reads the file from its end, in growing windows, until an intact record is found.
// Throws JournalError when the file cannot be read.
Tail find_tail(const std::string& path);

}  // namespace imess::journal
