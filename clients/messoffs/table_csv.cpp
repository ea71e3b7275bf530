// CSV offset tables: columns found by the header's names; every field checked like the JSON keys.
#include "table_csv.hpp"

#include <algorithm>
#include <array>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "field_checks.hpp"

namespace imess::messoffs {
namespace {

enum Column { kName, kClamping, kP, kX, kY, kZ, kA, kB, kDx, kDy, kDz, kColumns };
constexpr std::array<std::string_view, kColumns> kColumnNames = {"name", "clamping", "p", "x",  "y", "z",
                                                                  "a",    "b",        "dx", "dy", "dz"};
constexpr std::string_view kAccepted = "name, clamping, p, x, y, z, a, b, dx, dy, dz";

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    std::size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

using Header = std::array<std::optional<std::size_t>, kColumns>;  // column -> field index

Header read_header(std::string_view line, const std::string& where) {
  Header h;
  const auto fields = split(line);
  for (std::size_t i = 0; i < fields.size(); ++i) {
    auto it = std::find(kColumnNames.begin(), kColumnNames.end(), fields[i]);
    if (it == kColumnNames.end())
      throw TableError(where + ": header: unknown column '" + std::string(fields[i]) + "'; accepted: " +
                       std::string(kAccepted) + " (name, x, y, z, a, b required)");
    auto& slot = h[static_cast<std::size_t>(std::distance(kColumnNames.begin(), it))];
    if (slot) throw TableError(where + ": header: column '" + std::string(fields[i]) + "' appears twice");
    slot = i;
  }
  for (Column c : {kName, kX, kY, kZ, kA, kB})
    if (!h[c])
      throw TableError(where + ": header: column '" + std::string(kColumnNames[c]) +
                       "' missing (required: name, x, y, z, a, b; optional: clamping, p, dx, dy, dz)");
  return h;
}

OffsetEntry read_row(const Header& h, std::size_t header_fields, std::string_view line, const std::string& where) {
  const auto fields = split(line);
  if (fields.size() != header_fields)
    throw TableError(where + ": " + std::to_string(fields.size()) + " fields, the header has " +
                     std::to_string(header_fields));
  auto field = [&](Column c) -> std::optional<std::string_view> {
    if (!h[c] || fields[*h[c]].empty()) return std::nullopt;
    return fields[*h[c]];
  };
  auto at = [&](Column c) { return where + ": column '" + std::string(kColumnNames[c]) + "'"; };
  auto num = [&](Column c, std::string_view what, double fallback) {
    auto f = field(c);
    return f ? parse_number(*f, at(c), what) : fallback;
  };
  auto required = [&](Column c, std::string_view what) {
    if (!field(c)) throw TableError(at(c) + ": empty (expected " + std::string(what) + ")");
    return num(c, what, 0.0);
  };
  OffsetEntry e;
  if (!field(kName)) throw TableError(at(kName) + ": empty (expected an offset name such as G510)");
  e.name = check_name(*field(kName), at(kName));
  e.clamping = check_clamping(num(kClamping, "the clamping", 1.0), at(kClamping));
  if (field(kP))
    e.p = check_p(num(kP, "the P number", 0.0), at(kP));
  else
    e.p = implied_p(e.name);
  e.offset.axis[0] = {required(kX, "the base x in mm"), num(kDx, "the correction in mm", 0.0)};
  e.offset.axis[1] = {required(kY, "the base y in mm"), num(kDy, "the correction in mm", 0.0)};
  e.offset.axis[2] = {required(kZ, "the base z in mm"), num(kDz, "the correction in mm", 0.0)};
  e.offset.a_deg = required(kA, "the A angle in degrees");
  e.offset.b_deg = required(kB, "the B angle in degrees");
  return e;
}

}  // namespace

OffsetTable parse_table_csv(std::string_view text, std::string_view source) {
  const std::string src(source);
  OffsetTable table;
  std::optional<Header> header;
  std::size_t header_fields = 0;
  std::size_t line_no = 0;
  for (std::size_t pos = 0; pos < text.size();) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_no;
    if (line.empty() || line.front() == '#') continue;
    const std::string where = src + ":" + std::to_string(line_no);
    if (!header) {
      header = read_header(line, where);
      header_fields = split(line).size();
      continue;
    }
    table.rows.push_back(read_row(*header, header_fields, line, where));
  }
  if (!header)
    throw TableError(src + ": no header line (expected column names such as name,clamping,p,x,y,z,a,b,dx,dy,dz)");
  check_table(table, source);
  return table;
}

}  // namespace imess::messoffs
