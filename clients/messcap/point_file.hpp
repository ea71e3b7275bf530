// PointFile: the capture file. Each point is written and flushed to disk (fdatasync) the
// moment it arrives, so a crash or Ctrl-C loses nothing. Format from the extension:
// .csv = header "x,y,z" then "1.000,2.000,3.000"; .xyz = "1.000 2.000 3.000".
#pragma once
#include <string>
#include <string_view>

#include "imess/protocol/commands.hpp"

namespace imess::messcap {

enum class PointFormat { Csv, Xyz };

// Format for a file name by its extension (case-insensitive). Throws client::UsageError
// naming the file and the accepted extensions.
PointFormat format_for_path(std::string_view path);

// One point as a line of the file, without '\n'.
std::string format_point(PointFormat format, const protocol::Xyz& p);

enum class OpenMode {
  New,        // refuse to touch an existing file (default: never overwrite an earlier capture)
  Append,     // continue an existing file (a CSV header only if it is empty)
  Overwrite,  // replace it
};

class PointFile {
 public:
  // Creates/opens the file and writes the CSV header if needed. Throws std::runtime_error
  // naming the file and the reason.
  PointFile(std::string path, OpenMode mode);
  ~PointFile();
  PointFile(const PointFile&) = delete;
  PointFile& operator=(const PointFile&) = delete;

  // Writes one point and forces it to disk. Throws std::runtime_error on a write error.
  void append(const protocol::Xyz& p);

  // Closes and deletes the file if this run created it and wrote no point (the capture never
  // started, e.g. messd was not reachable).
  void discard_if_unused();

  const std::string& path() const { return path_; }
  int points() const { return points_; }

 private:
  void write_line(std::string line);

  std::string path_;
  PointFormat format_;
  int fd_ = -1;
  bool created_ = false;
  int points_ = 0;
};

}  // namespace imess::messcap
