// Hit numbers in capture files: the line formats .xyz, .asc and .hits carry each point's
// journal number as a trailing comment, "430.000 330.000 80.000 # hit 17", which every reader
// of those files (messcap fit/convert, FreeCAD's ASC import) skips as a comment.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace imess::messcap {

// Whether the file's format carries hit numbers (by extension: .xyz, .asc, .hits).
bool keeps_hit_numbers(const std::string& path);

// " # hit 17" (without "\n"), to follow a point's coordinates.
std::string hit_comment(std::uint64_t seq);

// The highest hit number in the file; none when it holds none or does not exist.
// Throws std::runtime_error when it exists but cannot be read.
std::optional<std::uint64_t> last_hit_number(const std::string& path);

}  // namespace imess::messcap
