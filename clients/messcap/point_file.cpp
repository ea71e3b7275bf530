// PointFile: O_APPEND line writes plus fdatasync for line formats, whole-file atomic rewrites
// (temporary file, fdatasync, rename) for the others — once per flush.
#include "point_file.hpp"

#include "hit_numbers.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
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
    if (::lseek(fd_, 0, SEEK_END) > 0) cut_unfinished_line();
    if (::lseek(fd_, 0, SEEK_END) == 0) append_text(capture_header(path_, format_->header()));
    else scan_column_ = csv_has_scan_column(path_);  // continued in the layout it has
  } else {
    ::close(fd_);  // the name is claimed; from now on the file is replaced whole
    fd_ = -1;
    rewrite();
  }
}

// A capture killed while writing may leave its last line unfinished (no "\n"): that point was
// never complete, and the capture continuing the file fetches it again by its number.
void PointFile::cut_unfinished_line() {
  std::ifstream in(path_, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.eof() && in.fail()) throw std::runtime_error("cannot read '" + path_ + "': " + std::strerror(errno));
  if (text.empty() || text.back() == '\n') return;
  const auto keep = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
  if (::ftruncate(fd_, static_cast<off_t>(keep)) != 0)
    throw std::runtime_error("cannot cut the unfinished last line of '" + path_ + "': " + std::strerror(errno));
  cut_line_ = text.substr(keep);
}

PointFile::~PointFile() {
  if (fd_ >= 0) ::close(fd_);
}

void PointFile::append_text(const std::string& text) {
  if (!text.empty()) write_all(fd_, text, path_);
}

void PointFile::rewrite() { write_file_atomically(path_, format_->write(data_)); }

void PointFile::append(const Eigen::Vector3d& p, const std::optional<PointNumber>& number) {
  if (needs_approach())
    throw std::logic_error("'" + path_ + "' holds hits with approach direction and tip radius; a point without them "
                           "cannot be written to it");
  add(p, nullptr, number);
}

void PointFile::append(const metrology::ProbedPoint& h, const std::optional<PointNumber>& number) {
  add(h.surface, &h, number);
}

void PointFile::add(const Eigen::Vector3d& p, const metrology::ProbedPoint* h, const std::optional<PointNumber>& number) {
  if (format_->appendable()) {
    std::string line = needs_approach() ? format_->hit_line(*h, data_.decimals) : format_->point_line(p, data_.decimals);
    pending_ += with_hit_number(path_, std::move(line), number, scan_column_);
  } else {
    data_.points.push_back(p);
    rewrite_due_ = true;
  }
  ++points_;
}

void PointFile::flush() {
  if (format_->appendable()) {
    append_text(pending_);
    pending_.clear();
  } else if (rewrite_due_) {
    rewrite();
    rewrite_due_ = false;
  }
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
