// JSON offset tables: every key checked, unknown keys named with the ones accepted.
#include "table_json.hpp"

#include <algorithm>
#include <iterator>

#include <nlohmann/json.hpp>

#include "imess/jsontext/strict_json.hpp"

#include "field_checks.hpp"

namespace imess::messoffs {
namespace {

using nlohmann::json;

constexpr std::string_view kRowKeys = "name, clamping, p, a, b, x, y, z";

double number(const json& v, const std::string& where, std::string_view what) {
  if (!v.is_number()) throw TableError(where + ": expected " + std::string(what) + ", got " + v.dump());
  return check_finite(v.get<double>(), where, what);
}

metrology::AxisValue axis_value(const json& v, const std::string& where) {
  if (v.is_array()) {
    if (v.size() != 2) throw TableError(where + ": expected [base, correction] (mm), got " + v.dump());
    return {number(v[0], where + "[0]", "the base in mm"), number(v[1], where + "[1]", "the correction in mm")};
  }
  return {number(v, where, "a number (the base in mm) or [base, correction]"), 0.0};
}

OffsetEntry parse_row(const json& row, const std::string& where) {
  if (!row.is_object()) throw TableError(where + ": expected an object with " + std::string(kRowKeys));
  static constexpr std::string_view kKeys[] = {"name", "clamping", "p", "a", "b", "x", "y", "z"};
  for (const auto& [key, value] : row.items())
    if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys))
      throw TableError(where + "." + key + ": unknown key; accepted: " + std::string(kRowKeys));
  auto need = [&](const char* key) -> const json& {
    auto it = row.find(key);
    if (it == row.end()) throw TableError(where + "." + key + ": missing (each offset needs name, x, y, z, a, b)");
    return *it;
  };
  OffsetEntry e;
  const json& name = need("name");
  if (!name.is_string()) throw TableError(where + ".name: expected a string such as \"G510\", got " + name.dump());
  e.name = check_name(name.get<std::string>(), where + ".name");
  if (auto it = row.find("clamping"); it != row.end())
    e.clamping = check_clamping(number(*it, where + ".clamping", "the clamping"), where + ".clamping");
  if (auto it = row.find("p"); it != row.end())
    e.p = check_p(number(*it, where + ".p", "the P number"), where + ".p");
  else
    e.p = implied_p(e.name);
  const char* axes[] = {"x", "y", "z"};
  for (std::size_t k = 0; k < 3; ++k) e.offset.axis[k] = axis_value(need(axes[k]), where + "." + axes[k]);
  e.offset.a_deg = number(need("a"), where + ".a", "the A angle in degrees");
  e.offset.b_deg = number(need("b"), where + ".b", "the B angle in degrees");
  return e;
}

}  // namespace

OffsetTable parse_table_json(std::string_view text, std::string_view source) {
  const std::string src(source);
  json doc;
  try {
    doc = jsontext::parse_strict(text, source);
  } catch (const jsontext::JsonTextError& e) {
    throw TableError(e.what());
  }
  if (!doc.is_object()) throw TableError(src + ": expected a JSON object with an \"offsets\" array");
  for (const auto& [key, value] : doc.items()) {
    if (key == "offsets") continue;
    if (key == "units") {
      if (value != "mm") throw TableError(src + ": units: only \"mm\" is accepted, got " + value.dump());
      continue;
    }
    throw TableError(src + ": " + key + ": unknown key; accepted: units, offsets");
  }
  const auto offsets = doc.find("offsets");
  if (offsets == doc.end() || !offsets->is_array())
    throw TableError(src + ": offsets: missing or not an array (expected one object per offset)");
  OffsetTable table;
  for (std::size_t i = 0; i < offsets->size(); ++i)
    table.rows.push_back(parse_row((*offsets)[i], src + ": offsets[" + std::to_string(i) + "]"));
  check_table(table, source);
  return table;
}

std::string table_to_json(const OffsetTable& table) {
  using ordered = nlohmann::ordered_json;  // keys in the documented order
  std::string out = "{\n  \"units\": \"mm\",\n  \"offsets\": [\n";
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto& e = table.rows[i];
    ordered row = ordered::object();
    row["name"] = e.name;
    row["clamping"] = e.clamping;
    if (e.p) row["p"] = *e.p;
    const char* axes[] = {"x", "y", "z"};
    for (std::size_t k = 0; k < 3; ++k) row[axes[k]] = ordered::array({e.offset.axis[k].base, e.offset.axis[k].correction});
    row["a"] = e.offset.a_deg;
    row["b"] = e.offset.b_deg;
    out += "    " + row.dump() + (i + 1 < table.rows.size() ? ",\n" : "\n");  // one offset per line
  }
  return out + "  ]\n}\n";
}

}  // namespace imess::messoffs
