// The offset table as CSV: a header line naming the columns (any order), one offset per line,
// '#' comment lines and blank lines skipped. Columns: docs/clients.md.
#pragma once
#include <string_view>

#include "offset_table.hpp"

namespace imess::messoffs {

// Throws TableError "<source>:<line>: column '<name>': <what is accepted>".
OffsetTable parse_table_csv(std::string_view text, std::string_view source = "<csv>");

}  // namespace imess::messoffs
