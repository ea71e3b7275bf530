// Hit numbers in capture files: .csv has a first column `hit` and a last column `scan` (header
// "hit,x,y,z,scan"); the line formats .xyz, .asc and .hits carry the number as a trailing
// comment, "430.000 330.000 80.000 # hit 17" (a scan's point "… # hit 17 scan 5", the scan's
// id after it), which every reader of those files (messcap fit/convert, FreeCAD's ASC import)
// skips.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace imess::messcap {

// A captured point's number in messd's journal and, for a scan's point (a `Scan` line), the
// id of the scan that took it.
struct PointNumber {
  std::uint64_t seq = 0;
  std::optional<std::uint64_t> scan;
};

// Whether the file's format carries hit numbers (by extension: .csv, .xyz, .asc, .hits).
bool keeps_hit_numbers(const std::string& path);

// " # hit 17", " # hit 17 scan 5" (without "\n"), to follow a point's coordinates.
std::string hit_comment(const PointNumber& number);

// A capture file's header: "hit,x,y,z,scan\n" for .csv, else the format's own (`format_header`).
std::string capture_header(const std::string& path, const std::string& format_header);
// Whether an existing .csv's header has the `scan` column (a capture's of an older messcap is
// "hit,x,y,z"): continued in its own layout. False for a file that is missing or empty.
bool csv_has_scan_column(const std::string& path);
// One point's line (`line`, with its "\n") with its hit number in the file's way: .csv
// "17,430.000,330.000,80.000," and a scan's point "18,430.000,330.000,80.000,5" (`scan_column`:
// the file has that column; the first field empty when there is no number), the others a comment.
std::string with_hit_number(const std::string& path, std::string line, const std::optional<PointNumber>& number,
                            bool scan_column = true);

// The highest hit number in the file; none when it holds none or does not exist. Throws
// std::runtime_error when it exists but cannot be read, and for a .csv without the `hit`
// column (it cannot be continued without a gap), saying which files can.
std::optional<std::uint64_t> last_hit_number(const std::string& path);

}  // namespace imess::messcap
