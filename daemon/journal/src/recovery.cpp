// find_tail(): backwards over the lines of the newest file to its last intact record.
#include "recovery.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string_view>

#include "imess/journal/journal_config.hpp"
#include "imess/journal/record.hpp"

namespace imess::journal {
namespace {

std::string read_range(int fd, std::uint64_t offset, std::uint64_t size, const std::string& path) {
  std::string buf(size, '\0');
  std::uint64_t done = 0;
  while (done < size) {
    ssize_t n = ::pread(fd, buf.data() + done, size - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw JournalError("cannot read the journal file '" + path + "': " + std::strerror(errno));
    if (n == 0) break;
    done += static_cast<std::uint64_t>(n);
  }
  buf.resize(done);
  return buf;
}

}  // namespace

Tail find_tail(const std::string& path) {
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw JournalError("cannot open the journal file '" + path + "': " + std::strerror(errno));
  struct stat st {};
  ::fstat(fd, &st);
  Tail tail;
  tail.file_bytes = static_cast<std::uint64_t>(st.st_size);
  try {
    for (std::uint64_t window = 64 * 1024;; window *= 4) {
      const std::uint64_t start = window >= tail.file_bytes ? 0 : tail.file_bytes - window;
      std::string text = read_range(fd, start, tail.file_bytes - start, path);
      // Only lines ending in "\n" can be records; anything after the last "\n" is torn.
      std::size_t end = text.rfind('\n');
      while (end != std::string::npos) {
        std::size_t begin = end == 0 ? std::string::npos : text.rfind('\n', end - 1);
        if (begin == std::string::npos && start > 0) break;  // the line may begin before the window
        std::size_t from = begin == std::string::npos ? 0 : begin + 1;
        if (auto r = decode_record(std::string_view(text).substr(from, end - from))) {
          tail.last_seq = r->seq;
          tail.good_bytes = start + end + 1;
          ::close(fd);
          return tail;
        }
        end = begin;
      }
      if (start == 0) break;
    }
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return tail;  // no intact record at all
}

}  // namespace imess::journal
