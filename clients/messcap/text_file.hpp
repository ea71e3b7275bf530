// Whole text files for messcap's commands: read one, or write one in place of the old (a
// temporary file renamed over it, so a reader never sees half a report).
#pragma once

#include <string>

namespace imess::messcap {

// Throws std::runtime_error "cannot read 'PATH': reason".
std::string read_text_file(const std::string& path);
// "-" writes to stdout. Throws std::runtime_error "cannot write 'PATH': reason".
void write_text_file(const std::string& path, const std::string& text);

}  // namespace imess::messcap
