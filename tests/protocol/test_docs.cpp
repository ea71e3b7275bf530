// docs/protocol.md stays true: every verb and every error code of the code is documented.
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "imess/protocol/error_code.hpp"
#include "imess/protocol/line_framer.hpp"
#include "imess/protocol/verbs.hpp"

using namespace imess::protocol;

namespace {
std::string read_doc() {
  std::ifstream in(std::string(IMESS_SOURCE_DIR) + "/docs/protocol.md");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

namespace {
// The rows of the markdown table that follows `heading`: first cell (without backticks) ->
// second cell (without backticks).
std::map<std::string, std::string> table_after(const std::string& doc, const std::string& heading) {
  std::map<std::string, std::string> rows;
  auto at = doc.find(heading);
  if (at == std::string::npos) return rows;
  std::istringstream in(doc.substr(at));
  std::string line;
  bool in_table = false;
  auto unquote = [](std::string cell) {
    std::erase(cell, '`');
    while (!cell.empty() && cell.front() == ' ') cell.erase(0, 1);
    while (!cell.empty() && cell.back() == ' ') cell.pop_back();
    return cell;
  };
  while (std::getline(in, line)) {
    if (line.rfind("|", 0) != 0) {
      if (in_table) break;
      continue;
    }
    in_table = true;
    auto c1 = line.find('|', 1);
    auto c2 = line.find('|', c1 + 1);
    std::string first = unquote(line.substr(1, c1 - 1));
    if (first.empty() || first.find("---") != std::string::npos || first == "verb" || first == "name") continue;
    rows[first] = unquote(line.substr(c1 + 1, c2 - c1 - 1));
  }
  return rows;
}
}  // namespace

TEST_CASE("docs/protocol.md's verb table and the declarations agree: names and usage") {
  auto doc = read_doc();
  REQUIRE_FALSE(doc.empty());
  auto documented = table_after(doc, "## Client → daemon");
  REQUIRE(documented.size() >= 10);
  std::set<std::string> declared;
  for (const auto& v : verb_table()) {
    INFO(v.name);
    declared.insert(std::string(v.name));
    REQUIRE(documented.count(std::string(v.name)) == 1);
    CHECK(documented[std::string(v.name)] == usage_args(v));  // the arguments column is the usage
  }
  for (const auto& [name, args] : documented) {
    INFO("documented but not declared: " << name);
    CHECK(declared.count(name) == 1);
  }
}

TEST_CASE("docs/protocol.md lists every error code with its name") {
  auto doc = read_doc();
  for (const auto& e : error_table()) {
    INFO(e.name);
    CHECK(doc.find("| " + std::to_string(static_cast<int>(e.code)) + " | " + std::string(e.name) + " |") !=
          std::string::npos);
  }
  CHECK(doc.find("Maximum line length: " + std::to_string(kMaxLineLength)) != std::string::npos);
}
