// PointFile: O_APPEND writes of whole lines plus fdatasync, one point at a time.
#include "point_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "imess/client/usage_error.hpp"
#include "imess/protocol/numbers.hpp"

namespace imess::messcap {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

PointFormat format_for_path(std::string_view path) {
  auto slash = path.rfind('/');
  auto name = slash == std::string_view::npos ? path : path.substr(slash + 1);
  auto dot = name.rfind('.');
  std::string ext = dot == std::string_view::npos ? "" : lower(name.substr(dot));
  if (ext == ".csv") return PointFormat::Csv;
  if (ext == ".xyz") return PointFormat::Xyz;
  throw client::UsageError("output file '" + std::string(path) + "': " +
                           (ext.empty() ? std::string("no extension") : "unknown extension '" + ext + "'") +
                           "; accepted: .csv (x,y,z with a header line) or .xyz (x y z)");
}

std::string format_point(PointFormat format, const protocol::Xyz& p) {
  char sep = format == PointFormat::Csv ? ',' : ' ';
  std::string s;
  protocol::append_mm(s, p.x);
  s.push_back(sep);
  protocol::append_mm(s, p.y);
  s.push_back(sep);
  protocol::append_mm(s, p.z);
  return s;
}

PointFile::PointFile(std::string path, OpenMode mode) : path_(std::move(path)), format_(format_for_path(path_)) {
  struct stat st {};
  bool existed = ::stat(path_.c_str(), &st) == 0;
  int flags = O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC;
  if (mode == OpenMode::New) flags |= O_EXCL;
  if (mode == OpenMode::Overwrite) flags |= O_TRUNC;
  fd_ = ::open(path_.c_str(), flags, 0644);
  if (fd_ < 0) {
    if (errno == EEXIST)
      throw std::runtime_error("'" + path_ + "' exists; add --append to continue it or --force to replace it");
    throw std::runtime_error("cannot open '" + path_ + "' for writing: " + std::strerror(errno));
  }
  created_ = !existed;
  if (format_ == PointFormat::Csv && ::lseek(fd_, 0, SEEK_END) == 0) write_line("x,y,z");
}

PointFile::~PointFile() {
  if (fd_ >= 0) ::close(fd_);
}

void PointFile::write_line(std::string line) {
  line.push_back('\n');
  std::size_t done = 0;
  while (done < line.size()) {
    ssize_t n = ::write(fd_, line.data() + done, line.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot write '" + path_ + "': " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
  if (::fdatasync(fd_) != 0 && errno != EINVAL)  // EINVAL: a pipe or device, nothing to sync
    throw std::runtime_error("cannot write '" + path_ + "' to disk: " + std::strerror(errno));
}

void PointFile::append(const protocol::Xyz& p) {
  write_line(format_point(format_, p));
  ++points_;
}

void PointFile::discard_if_unused() {
  if (fd_ < 0 || points_ > 0 || !created_) return;
  ::close(fd_);
  fd_ = -1;
  ::unlink(path_.c_str());
}

}  // namespace imess::messcap
