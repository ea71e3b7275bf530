// Hit numbers in capture files: .csv has a first column `hit` (header "hit,x,y,z"); the line
// formats .xyz, .asc and .hits carry the number as a trailing comment, "430.000 330.000 80.000
// # hit 17", which every reader of those files (messcap fit/convert, FreeCAD's ASC import) skips.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace imess::messcap {

// Whether the file's format carries hit numbers (by extension: .csv, .xyz, .asc, .hits).
bool keeps_hit_numbers(const std::string& path);

// " # hit 17" (without "\n"), to follow a point's coordinates.
std::string hit_comment(std::uint64_t seq);

// A capture file's header: "hit,x,y,z\n" for .csv, else the format's own (`format_header`).
std::string capture_header(const std::string& path, const std::string& format_header);
// One point's line (`line`, with its "\n") with its hit number in the file's way: .csv
// "17,430.000,330.000,80.000" (an empty first field when there is no number), the others a comment.
std::string with_hit_number(const std::string& path, std::string line, std::optional<std::uint64_t> seq);

// The highest hit number in the file; none when it holds none or does not exist. Throws
// std::runtime_error when it exists but cannot be read, and for a .csv without the `hit`
// column (it cannot be continued without a gap), saying which files can.
std::optional<std::uint64_t> last_hit_number(const std::string& path);

}  // namespace imess::messcap
