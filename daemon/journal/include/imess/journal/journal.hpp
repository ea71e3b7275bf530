// Journal: numbers every measured point and appends it to a file before anyone is sent it;
// forces it to disk within the configured interval; rotates files by size; reads hits back
// for Replay. Used by the io thread only (not thread-safe, never real-time).
#pragma once
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "imess/journal/journal_config.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::journal {

struct JournalFile;
struct FileScan;

// Numbers journaled whose records cannot be read back (damaged: the checksum fails, or the
// line is gone). `before`: in ReadResult, the index in `lines` of the first hit after them.
struct LostRange {
  std::uint64_t first = 0, last = 0;
  std::size_t before = 0;
};

// What Journal::read found.
struct ReadResult {
  std::vector<std::string> lines;  // Hit lines as sent live, each with its "\n"
  std::vector<LostRange> lost;     // numbers among them that cannot be given, in order
  std::uint64_t covered = 0;       // from `from` on, the numbers given or named lost
  std::uint64_t newest = 0;        // the newest seq journaled
  bool rotated_away = false;       // `from` is older than the oldest file kept: nothing read
  std::uint64_t oldest = 0;        // the oldest seq still kept
};

class Journal {
 public:
  using Clock = std::chrono::steady_clock;

  // Creates the directory if needed, finds the last intact record (cutting off a torn end)
  // and opens the newest file for appending. Throws JournalError naming path and cause.
  explicit Journal(JournalConfig config);
  ~Journal();  // forces everything to disk
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  // Gives `hit` the next sequence number, writes it (write(2): a crash of messd after this
  // loses nothing) and returns the Hit line to send. With fsync_interval 0 it is on disk when
  // this returns. A write error throws JournalError; the number stays taken.
  std::string append(protocol::HitMsg& hit, Clock::time_point now = Clock::now());

  // fdatasync when the oldest unsynced hit is fsync_interval old. Call often (every ms).
  void sync_if_due(Clock::time_point now = Clock::now());
  // When sync_if_due will sync: the oldest unsynced hit's time plus fsync_interval; none when
  // everything is on disk.
  std::optional<Clock::time_point> sync_due() const {
    if (!unsynced_since_) return std::nullopt;
    return *unsynced_since_ + config_.fsync_interval;
  }
  void sync();

  // Up to `max` hits from `from` on (from 0 means 1). Throws JournalError on a read error.
  ReadResult read(std::uint64_t from, std::size_t max) const;

  std::uint64_t newest() const { return newest_; }  // 0: no hit yet
  std::uint64_t oldest() const;                     // newest + 1 when empty
  const std::string& dir() const { return config_.dir; }
  // What start-up found, for the log ("continuing after hit 41 in ...", "cut off a torn ...").
  const std::vector<std::string>& notes() const { return notes_; }
  // What start-up found damaged, for the log as warnings: one line per lost range, naming it.
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::vector<LostRange>& lost() const { return lost_; }  // found at start, in order

 private:
  void open_file(std::uint64_t first_seq);
  void rotate(std::uint64_t first_seq);
  void drop_old_files();
  void find_lost(const std::vector<FileScan>& scans);  // at start, all files still in files_
  void note_lost();                                     // the log lines for what find_lost found

  JournalConfig config_;
  std::vector<JournalFile> files_;  // oldest first; the last one is written
  int fd_ = -1;
  std::uint64_t size_ = 0;          // bytes in the file being written
  std::uint64_t newest_ = 0;
  std::optional<Clock::time_point> unsynced_since_;
  std::vector<std::string> notes_, warnings_;
  std::vector<LostRange> lost_;
};

}  // namespace imess::journal
