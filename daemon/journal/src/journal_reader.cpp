// Journal::read — Replay's source: from the file that holds `from`, line by line, the
// checksums checked, across rotated files, at most `max` hits; numbers without an intact
// record among them (damaged, missing) are reported as lost ranges in their place.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "imess/journal/journal.hpp"
#include "imess/journal/record.hpp"
#include "journal_files.hpp"

namespace imess::journal {

ReadResult Journal::read(std::uint64_t from, std::size_t max) const {
  ReadResult out;
  out.newest = newest_;
  out.oldest = oldest();
  if (from == 0) from = 1;
  if (from < out.oldest) {
    out.rotated_away = true;
    return out;
  }
  if (from > newest_ || max == 0) return out;
  // The last file whose first number is not after `from`.
  std::size_t i = files_.size() - 1;
  while (i > 0 && files_[i].first > from) --i;
  std::uint64_t want = from;
  std::string buf(64 * 1024, '\0'), line;
  for (; i < files_.size() && out.lines.size() < max; ++i) {
    int fd = ::open(files_[i].path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw JournalError("cannot open the journal file '" + files_[i].path + "': " + std::strerror(errno));
    for (;;) {
      ssize_t n = ::read(fd, buf.data(), buf.size());
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        std::string why = std::strerror(errno);
        ::close(fd);
        throw JournalError("cannot read the journal file '" + files_[i].path + "': " + why);
      }
      if (n == 0) break;
      std::string_view chunk(buf.data(), static_cast<std::size_t>(n));
      while (!chunk.empty() && out.lines.size() < max) {
        auto nl = chunk.find('\n');
        if (nl == std::string_view::npos) {
          line.append(chunk);
          break;
        }
        line.append(chunk.substr(0, nl));
        chunk.remove_prefix(nl + 1);
        auto seq = record_seq(line);
        if (seq && *seq >= want) {  // before it: skipped without checking the checksum
          if (auto r = decode_record(line)) {
            if (r->seq > want) out.lost.push_back({want, r->seq - 1, out.lines.size()});
            out.lines.emplace_back(std::string(r->wire) + "\n");
            want = r->seq + 1;
          }
        }
        line.clear();
      }
      if (out.lines.size() >= max) break;
    }
    ::close(fd);
    line.clear();
  }
  if (out.lines.size() < max && want <= newest_) {  // the journal's last numbers have no record
    out.lost.push_back({want, newest_, out.lines.size()});
    want = newest_ + 1;
  }
  out.covered = want - from;
  return out;
}

}  // namespace imess::journal
