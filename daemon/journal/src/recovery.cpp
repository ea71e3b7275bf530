// scan_file(): one pass over a journal file's lines; check_files_agree(): the files' numbers
// against their names and each other, so a stray file never makes a number be given again.
#include "recovery.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string_view>

#include "imess/journal/journal_config.hpp"
#include "imess/journal/record.hpp"

namespace imess::journal {
namespace {

void take_line(std::string_view line, std::uint64_t end_offset, const JournalFile& file, FileScan& s) {
  auto r = decode_record(line);
  if (!r) return;  // damaged: its number shows as a gap between the intact ones
  if (s.highest && r->seq <= *s.highest) {
    if (!s.out_of_order) {
      s.out_of_order = r->seq;
      s.after = *s.highest;
    }
    return;
  }
  const std::uint64_t expected = s.highest ? *s.highest + 1 : file.first;
  if (r->seq > expected) s.gaps.push_back({expected, r->seq - 1, 0});
  if (!s.lowest) s.lowest = r->seq;
  s.highest = r->seq;
  s.good_bytes = end_offset;
}

std::string what_it_holds(const FileScan& s) {
  if (!s.highest) return "holds no intact hit";
  return "holds hits " + std::to_string(*s.lowest) + " to " + std::to_string(*s.highest);
}

std::string what_to_do(const std::string& dir) {
  return ": move it out of '" + dir + "' (or delete it if its hits do not matter) and start messd again (it does not "
         "start rather than give hit numbers a second time)";
}

}  // namespace

FileScan scan_file(const JournalFile& file) {
  int fd = ::open(file.path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw JournalError("cannot open the journal file '" + file.path + "': " + std::strerror(errno));
  FileScan s;
  std::string buf(64 * 1024, '\0'), line;
  std::uint64_t offset = 0;  // of the chunk's first byte
  for (;;) {
    ssize_t n = ::read(fd, buf.data(), buf.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      std::string why = std::strerror(errno);
      ::close(fd);
      throw JournalError("cannot read the journal file '" + file.path + "': " + why);
    }
    if (n == 0) break;
    std::string_view chunk(buf.data(), static_cast<std::size_t>(n));
    std::size_t pos = 0;
    for (auto nl = chunk.find('\n'); nl != std::string_view::npos; nl = chunk.find('\n', pos)) {
      line.append(chunk.substr(pos, nl - pos));
      take_line(line, offset + nl + 1, file, s);
      line.clear();
      pos = nl + 1;
    }
    line.append(chunk.substr(pos));  // a line that goes on in the next chunk, or a torn end
    offset += static_cast<std::uint64_t>(n);
  }
  ::close(fd);
  s.file_bytes = offset;
  return s;
}

void check_files_agree(const std::vector<JournalFile>& files, const std::vector<FileScan>& scans,
                       const std::string& dir) {
  for (std::size_t i = 0; i + 1 < files.size(); ++i) {
    const FileScan &a = scans[i], &b = scans[i + 1];
    if (!a.highest || *a.highest < files[i + 1].first) continue;
    // The one with fewer intact hits is most likely the one that does not belong.
    const bool b_stray = !b.highest || (*b.highest - *b.lowest) <= (*a.highest - *a.lowest);
    const std::string& stray = b_stray ? files[i + 1].path : files[i].path;
    throw JournalError("the journal files '" + files[i].path + "' and '" + files[i + 1].path + "' in '" + dir +
                       "' cannot both belong to this journal: the first holds hits up to " +
                       std::to_string(*a.highest) + ", but the name of the second says its hits begin at " +
                       std::to_string(files[i + 1].first) + " (continuing would give those numbers again), and the " +
                       "second " + what_it_holds(b) + ". The one that does not belong is probably '" + stray + "'" +
                       what_to_do(dir));
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    const FileScan& s = scans[i];
    if (s.lowest && *s.lowest < files[i].first)
      throw JournalError("the journal file '" + files[i].path + "' holds hit " + std::to_string(*s.lowest) +
                         ", but its name says its hits begin at " + std::to_string(files[i].first) +
                         " (renamed, or copied from another journal); it does not belong here" + what_to_do(dir));
    if (s.out_of_order)
      throw JournalError("the journal file '" + files[i].path + "' holds hit " + std::to_string(*s.out_of_order) +
                         " after hit " + std::to_string(*s.after) + " (joined or edited: a journal only grows); it " +
                         "does not belong here" + what_to_do(dir));
  }
}

}  // namespace imess::journal
