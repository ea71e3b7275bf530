// PointFile: O_APPEND line writes plus fdatasync for line formats, whole-file atomic rewrites
// (temporary file, fdatasync, rename) for the others.
#include "point_file.hpp"

#include "hit_numbers.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace imess::messcap {
namespace {

void write_all(int fd, const std::string& text, const std::string& path) {
  std::size_t done = 0;
  while (done < text.size()) {
    ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
  if (::fdatasync(fd) != 0 && errno != EINVAL)  // EINVAL: a pipe or device, nothing to sync
    throw std::runtime_error("cannot write '" + path + "' to disk: " + std::strerror(errno));
}

std::string base_name(const std::string& path) {
  auto slash = path.rfind('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot open '" + tmp + "' for writing: " + std::strerror(errno));
  try {
    write_all(fd, text, tmp);
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  ::close(fd);
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    int e = errno;
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot replace '" + path + "': " + std::strerror(e));
  }
}

PointFile::PointFile(std::string path, OpenMode mode, exchange::ExportData base)
    : path_(std::move(path)), format_(&exchange::export_format_for(path_)), data_(std::move(base)) {
  data_.points.clear();
  data_.file_name = base_name(path_);
  struct stat st {};
  const bool existed = ::stat(path_.c_str(), &st) == 0;
  if (mode == OpenMode::Append && !format_->appendable())
    throw std::runtime_error("'" + path_ + "' is written whole and cannot be continued; --append works with " +
                             exchange::appendable_extensions());
  int flags = O_WRONLY | O_CREAT | O_CLOEXEC | (format_->appendable() ? O_APPEND : 0);
  if (mode == OpenMode::New) flags |= O_EXCL;
  if (mode == OpenMode::Overwrite) flags |= O_TRUNC;
  fd_ = ::open(path_.c_str(), flags, 0644);
  if (fd_ < 0) {
    if (errno == EEXIST)
      throw std::runtime_error("'" + path_ + "' exists; add --append to continue it or --force to replace it");
    throw std::runtime_error("cannot open '" + path_ + "' for writing: " + std::strerror(errno));
  }
  created_ = !existed;
  if (format_->appendable()) {
    if (::lseek(fd_, 0, SEEK_END) == 0) append_text(capture_header(path_, format_->header()));
  } else {
    ::close(fd_);  // the name is claimed; from now on the file is replaced whole
    fd_ = -1;
    rewrite();
  }
}

PointFile::~PointFile() {
  if (fd_ >= 0) ::close(fd_);
}

void PointFile::append_text(const std::string& text) {
  if (!text.empty()) write_all(fd_, text, path_);
}

void PointFile::rewrite() { write_file_atomically(path_, format_->write(data_)); }

void PointFile::append(const Eigen::Vector3d& p, std::optional<std::uint64_t> hit) {
  if (needs_approach())
    throw std::logic_error("'" + path_ + "' holds hits with approach direction and tip radius; a point without them "
                           "cannot be written to it");
  add(p, nullptr, hit);
}

void PointFile::append(const metrology::ProbedPoint& h, std::optional<std::uint64_t> hit) { add(h.surface, &h, hit); }

void PointFile::add(const Eigen::Vector3d& p, const metrology::ProbedPoint* h, std::optional<std::uint64_t> hit) {
  if (format_->appendable()) {
    std::string line = needs_approach() ? format_->hit_line(*h, data_.decimals) : format_->point_line(p, data_.decimals);
    append_text(with_hit_number(path_, std::move(line), hit));
  } else {
    data_.points.push_back(p);
    rewrite();
  }
  ++points_;
}

void PointFile::set_fit(const exchange::FitReport& fit) {
  if (format_->appendable()) return;
  data_.fit = fit;
  rewrite();
}

void PointFile::discard_if_unused() {
  if (points_ > 0 || !created_) return;
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  ::unlink(path_.c_str());
  created_ = false;
}

}  // namespace imess::messcap
