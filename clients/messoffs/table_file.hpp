// Reading an offset table from a file (the format by its extension: .json or .csv) and writing
// messoffs's outputs whole (temporary file renamed over the target: never half a program).
#pragma once
#include <string>

#include "offset_table.hpp"

namespace imess::messoffs {

// Throws TableError naming the file: unreadable, not .json / .csv, or what its parser says.
OffsetTable load_table(const std::string& path);

// Writes `text` to PATH.tmp and renames it over `path`. An existing file is replaced only with
// `replace`. Throws std::runtime_error naming the file and the reason.
void write_output_file(const std::string& path, const std::string& text, bool replace);

}  // namespace imess::messoffs
