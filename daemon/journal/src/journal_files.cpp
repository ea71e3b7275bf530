// Naming, listing and directory upkeep for the journal files.
#include "journal_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "imess/journal/journal_config.hpp"
#include "imess/protocol/numbers.hpp"

namespace imess::journal {

namespace fs = std::filesystem;

std::string journal_file_name(std::uint64_t first_seq) {
  char name[40];
  std::snprintf(name, sizeof name, "hits-%012llu.jnl", static_cast<unsigned long long>(first_seq));
  return name;
}

std::vector<JournalFile> list_journal_files(const std::string& dir) {
  std::vector<JournalFile> files;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (name.size() < 10 || name.rfind("hits-", 0) != 0 || name.substr(name.size() - 4) != ".jnl") continue;
    auto first = protocol::parse_sequence_number(std::string_view(name).substr(5, name.size() - 9));
    if (first) files.push_back({*first, it->path().string()});
  }
  if (ec) throw JournalError("cannot read the journal directory '" + dir + "': " + ec.message());
  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return files;
}

void sync_directory(const std::string& dir) {
  int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

void prepare_directory(const std::string& dir) {
  if (dir.empty()) throw JournalError("the journal directory is empty; give one with --journal DIR");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw JournalError("cannot create the journal directory '" + dir + "': " +
                       (ec ? ec.message() : std::string("it exists and is not a directory")) +
                       "; give a writable directory with --journal DIR or \"journal\": {\"dir\": ...}");
  const std::string probe = dir + "/.messd-write-test";
  int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0 || ::write(fd, "ok\n", 3) != 3) {
    std::string why = std::strerror(errno);
    if (fd >= 0) ::close(fd);
    throw JournalError("cannot write in the journal directory '" + dir + "': " + why +
                       "; give a writable directory with --journal DIR or \"journal\": {\"dir\": ...}");
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace imess::journal
