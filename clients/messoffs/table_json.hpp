// The offset table as JSON: read (an axis as a number or as [base, correction]) and written
// (always [base, correction], one offset per line, numbers that round-trip exactly). Layout:
// docs/clients.md.
#pragma once
#include <string>
#include <string_view>

#include "offset_table.hpp"

namespace imess::messoffs {

// Throws TableError "<source>: offsets[i].<key>: <what is accepted>".
OffsetTable parse_table_json(std::string_view text, std::string_view source = "<json>");
std::string table_to_json(const OffsetTable& table);

}  // namespace imess::messoffs
