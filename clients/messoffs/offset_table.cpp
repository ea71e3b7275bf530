// Offset table rules: finding a row, the names and P numbers a CNC user expects.
#include "offset_table.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace imess::messoffs {

OffsetEntry& OffsetTable::find(std::string_view name, std::optional<int> clamping) {
  std::vector<OffsetEntry*> hits;
  for (auto& row : rows)
    if (row.name == name && (!clamping || row.clamping == *clamping)) hits.push_back(&row);
  if (hits.size() == 1) return *hits.front();
  if (hits.empty()) {
    std::string names;
    for (const auto& row : rows)
      if (!clamping || row.clamping == *clamping)
        names += (names.empty() ? "" : ", ") + row.name;
    throw TableError("no offset '" + std::string(name) + "'" +
                     (clamping ? " in clamping " + std::to_string(*clamping) : std::string()) +
                     "; the table has: " + (names.empty() ? std::string("none") : names));
  }
  std::string where;
  for (const auto* row : hits) where += (where.empty() ? "" : ", ") + std::to_string(row->clamping);
  throw TableError("offset '" + std::string(name) + "' is in clampings " + where +
                   "; choose one with --clamping N");
}

std::vector<int> OffsetTable::clampings() const {
  std::set<int> seen;
  for (const auto& row : rows) seen.insert(row.clamping);
  return {seen.begin(), seen.end()};
}

bool valid_offset_name(std::string_view name) {
  if (name.empty() || name.size() > 32) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
           c == '-';
  });
}

std::optional<int> implied_p(std::string_view name) {
  static const std::pair<std::string_view, int> kImplied[] = {
      {"G54", 1}, {"G55", 2}, {"G56", 3}, {"G57", 4}, {"G58", 5}, {"G59", 6}, {"G59.1", 7}, {"G59.2", 8}, {"G59.3", 9}};
  for (const auto& [word, p] : kImplied)
    if (name == word) return p;
  return std::nullopt;
}

void check_table(const OffsetTable& table, std::string_view source) {
  const std::string where(source);
  if (table.rows.empty()) throw TableError(where + ": no offsets (the table needs at least one row)");
  std::map<std::pair<int, std::string>, int> names;
  std::map<std::pair<int, int>, std::string> ps;
  for (const auto& row : table.rows) {
    const std::string in = " in clamping " + std::to_string(row.clamping);
    if (names[{row.clamping, row.name}]++ == 1)
      throw TableError(where + ": offset '" + row.name + "' appears twice" + in + " (a name once per clamping)");
    if (!row.p) continue;
    auto [it, fresh] = ps.emplace(std::pair{row.clamping, *row.p}, row.name);
    if (!fresh)
      throw TableError(where + ": offsets '" + it->second + "' and '" + row.name + "' both have P" +
                       std::to_string(*row.p) + in + " (a P number once per clamping)");
  }
}

}  // namespace imess::messoffs
