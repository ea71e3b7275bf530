// Start-up recovery: every journal file read through once — its intact records, the numbers
// between them that have none (damaged or missing records), and the torn or garbled bytes after
// the last one (a crash mid-write, zeros after a power cut) to be cut off the newest file.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "imess/journal/journal.hpp"
#include "journal_files.hpp"

namespace imess::journal {

struct FileScan {
  std::optional<std::uint64_t> lowest, highest;  // intact records; none: the file holds none
  std::vector<LostRange> gaps;  // numbers from the name's first to `highest` without an intact record
  std::optional<std::uint64_t> out_of_order, after;  // an intact hit not after the one before it
  std::uint64_t good_bytes = 0;  // the file up to and including the last intact record's "\n"
  std::uint64_t file_bytes = 0;
};

// Reads the file from its start. Throws JournalError when it cannot be read.
FileScan scan_file(const JournalFile& file);

// Throws JournalError naming the file and what to do when the files cannot all belong to one
// journal: hits in a file that its name does not give, or two files whose numbers overlap
// (continuing would give a number a second time). `dir`: for the message.
void check_files_agree(const std::vector<JournalFile>& files, const std::vector<FileScan>& scans,
                       const std::string& dir);

}  // namespace imess::journal
