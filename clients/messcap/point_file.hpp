// PointFile: the capture file, in the format of its extension. Points are taken by append()
// and put on disk by flush() — the capture flushes after each read from the connection, before
// it shows them, so one fdatasync covers the points that came together (a scan sends hundreds
// a second): line formats (.csv .xyz .asc .hits) get the lines appended; the others are
// rewritten whole into FILE.tmp, synced and renamed over FILE, so FILE is always a complete,
// valid document holding every point flushed.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "hit_numbers.hpp"
#include "imess/exchange/export_data.hpp"
#include "imess/exchange/export_format.hpp"

namespace imess::messcap {

enum class OpenMode {
  New,        // refuse to touch an existing file (default: never overwrite an earlier capture)
  Append,     // continue an existing line-format file (a CSV header only if it is empty)
  Overwrite,  // replace it
};

class PointFile {
 public:
  // Creates/opens the file and writes its empty document (CSV: the header "hit,x,y,z,scan"). `base` carries
  // the decimals, frame name, ... (its points are ignored). Throws std::runtime_error naming
  // the file and the reason; exchange::FormatError for an unknown extension.
  PointFile(std::string path, OpenMode mode, exchange::ExportData base = {});
  ~PointFile();
  PointFile(const PointFile&) = delete;
  PointFile& operator=(const PointFile&) = delete;

  // Takes one point for the next flush(); `number` (its journal number, and a scan's id) goes
  // into the formats that keep it (.csv's first and last columns, a comment in .xyz, .asc,
  // .hits: hit_numbers.hpp). Throws std::logic_error for a .hits file, which never takes a
  // point without its approach.
  void append(const Eigen::Vector3d& p, const std::optional<PointNumber>& number = std::nullopt);
  // The same for a hit or a scan's point: all of it (approach, tip radius) into .hits, its
  // surface point into the formats of plain points.
  void append(const metrology::ProbedPoint& h, const std::optional<PointNumber>& number = std::nullopt);
  // Writes the points taken since the last flush and forces them to disk (nothing when there
  // are none). Throws std::runtime_error on a write error.
  void flush();
  // Adds the fitted feature to the formats that hold one (.json, .dmi) and rewrites them.
  void set_fit(const exchange::FitReport& fit);

  // Deletes the file if this run created it and wrote no point (the capture never started,
  // e.g. messd was not reachable).
  void discard_if_unused();

  const std::string& path() const { return path_; }
  // --append: the unfinished last line (no "\n": a capture killed while writing it) cut off
  // the file when it was opened; empty when there was none.
  const std::string& cut_line() const { return cut_line_; }
  int points() const { return points_; }
  // .hits: every point needs the approach and tip radius of its hit.
  bool needs_approach() const { return format_->needs_approach(); }

 private:
  void append_text(const std::string& text);
  void cut_unfinished_line();
  void add(const Eigen::Vector3d& p, const metrology::ProbedPoint* h, const std::optional<PointNumber>& number);
  void rewrite();

  std::string path_;
  const exchange::ExportFormat* format_;
  exchange::ExportData data_;  // whole-file formats keep every point to rewrite the file
  int fd_ = -1;                // line formats: the open file
  bool created_ = false;
  std::string cut_line_;
  bool scan_column_ = true;    // .csv: the file's header has the `scan` column
  std::string pending_;        // line formats: the lines not yet flushed
  bool rewrite_due_ = false;   // whole-file formats: points not yet written
  int points_ = 0;
};

// Writes `text` to path.tmp, syncs it and renames it over `path` (a crash leaves either the
// old or the new file, never half of one). Throws std::runtime_error naming the file.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace imess::messcap
