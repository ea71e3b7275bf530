// The journal's files: "hits-<first seq, 12 digits>.jnl" in one directory, so the newest file
// and the file holding a given number follow from the names alone.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace imess::journal {

struct JournalFile {
  std::uint64_t first = 0;  // the sequence number of its first record
  std::string path;
};

std::string journal_file_name(std::uint64_t first_seq);

// The journal files in dir, oldest first; other files are left alone. Throws JournalError.
std::vector<JournalFile> list_journal_files(const std::string& dir);

// Makes a new directory entry durable (a power cut must not lose a new file's name).
void sync_directory(const std::string& dir);

// Creates dir (and its parents) if needed and proves it writable. Throws JournalError
// naming the directory and what to do.
void prepare_directory(const std::string& dir);

}  // namespace imess::journal
