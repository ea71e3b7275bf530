// Fuzz target: bytes -> messoffs's offset table, read as JSON and as CSV. The only exception
// allowed out of the parsers is TableError; a table that parses must come back unchanged
// through the JSON writer (the [base, correction] pairs round-trip exactly).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "table_csv.hpp"
#include "table_json.hpp"

namespace {

void check_round_trip(const imess::messoffs::OffsetTable& table) {
  const auto back = imess::messoffs::parse_table_json(imess::messoffs::table_to_json(table), "round-trip");
  if (back.rows.size() != table.rows.size()) std::abort();
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto& a = table.rows[i];
    const auto& b = back.rows[i];
    if (a.name != b.name || a.clamping != b.clamping || a.p != b.p || a.offset.a_deg != b.offset.a_deg ||
        a.offset.b_deg != b.offset.b_deg)
      std::abort();
    for (std::size_t k = 0; k < 3; ++k)
      if (a.offset.axis[k].base != b.offset.axis[k].base || a.offset.axis[k].correction != b.offset.axis[k].correction)
        std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    check_round_trip(imess::messoffs::parse_table_json(text, "fuzz.json"));
  } catch (const imess::messoffs::TableError&) {
  }
  try {
    check_round_trip(imess::messoffs::parse_table_csv(text, "fuzz.csv"));
  } catch (const imess::messoffs::TableError&) {
  }
  return 0;
}
