// Journal: start-up recovery, appending with fdatasync by interval, size rotation.
#include "imess/journal/journal.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "imess/journal/record.hpp"
#include "journal_files.hpp"
#include "recovery.hpp"

namespace imess::journal {

Journal::Journal(JournalConfig config) : config_(std::move(config)) {
  if (config_.files < 1) config_.files = 1;
  prepare_directory(config_.dir);
  files_ = list_journal_files(config_.dir);
  if (files_.empty()) {
    open_file(1);
    notes_.push_back("journal: new in " + config_.dir + ", the first hit will be 1");
    return;
  }
  // Every file is read through: the numbers must agree with the names (a stray file must not
  // restart the numbering), and every number without an intact record is named as lost.
  std::vector<FileScan> scans;
  for (const auto& f : files_) scans.push_back(scan_file(f));
  check_files_agree(files_, scans, config_.dir);
  // Numbering continues after the newest file's last intact record; a file without one
  // (begun just before a crash) continues after the number its name starts at.
  const JournalFile newest = files_.back();
  const FileScan& tail = scans.back();
  newest_ = tail.highest ? *tail.highest : newest.first - 1;
  find_lost(scans);
  if (tail.good_bytes < tail.file_bytes) {
    if (::truncate(newest.path.c_str(), static_cast<off_t>(tail.good_bytes)) != 0)
      throw JournalError("cannot cut the torn end off the journal file '" + newest.path + "': " + std::strerror(errno));
    notes_.push_back("journal: ignored " + std::to_string(tail.file_bytes - tail.good_bytes) +
                     " bytes of a torn last record in " + newest.path + " (a crash while writing)");
  }
  files_.pop_back();
  open_file(newest.first);
  drop_old_files();
  note_lost();
}

Journal::~Journal() {
  if (fd_ >= 0) {
    ::fdatasync(fd_);
    ::close(fd_);
  }
}

void Journal::open_file(std::uint64_t first_seq) {
  JournalFile f{first_seq, config_.dir + "/" + journal_file_name(first_seq)};
  fd_ = ::open(f.path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw JournalError("cannot open the journal file '" + f.path + "' for writing: " + std::strerror(errno));
  struct stat st {};
  ::fstat(fd_, &st);
  size_ = static_cast<std::uint64_t>(st.st_size);
  files_.push_back(std::move(f));
  sync_directory(config_.dir);
}

void Journal::rotate(std::uint64_t first_seq) {
  sync();
  ::close(fd_);
  fd_ = -1;
  open_file(first_seq);
  drop_old_files();
}

void Journal::drop_old_files() {
  while (files_.size() > config_.files) {
    ::unlink(files_.front().path.c_str());
    files_.erase(files_.begin());
  }
}

std::uint64_t Journal::oldest() const { return files_.empty() ? newest_ + 1 : files_.front().first; }

std::string Journal::append(protocol::HitMsg& hit, Clock::time_point now) {
  hit.seq = ++newest_;
  std::string wire = protocol::format_hit(hit);
  std::string record = encode_record(wire);
  if (size_ > 0 && size_ + record.size() > config_.max_bytes) rotate(hit.seq);
  std::size_t done = 0;
  while (done < record.size()) {
    ssize_t n = ::write(fd_, record.data() + done, record.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      std::string why = n < 0 ? std::strerror(errno) : "nothing written";
      // Never leave half a record for the next one to be glued to.
      if (::ftruncate(fd_, static_cast<off_t>(size_)) != 0) {}
      throw JournalError("cannot write hit " + std::to_string(hit.seq) + " to the journal file '" + files_.back().path +
                         "': " + why);
    }
    done += static_cast<std::size_t>(n);
  }
  size_ += record.size();
  if (!unsynced_since_) unsynced_since_ = now;
  if (config_.fsync_interval.count() == 0) sync();
  return wire;
}

void Journal::sync_if_due(Clock::time_point now) {
  if (unsynced_since_ && now - *unsynced_since_ >= config_.fsync_interval) sync();
}

void Journal::sync() {
  if (fd_ >= 0 && unsynced_since_) ::fdatasync(fd_);
  unsynced_since_.reset();
}

}  // namespace imess::journal
