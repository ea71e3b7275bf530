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
#include "doc_table.hpp"

using namespace imess::protocol;

namespace {
std::string read_doc() {
  std::ifstream in(std::string(IMESS_SOURCE_DIR) + "/docs/protocol.md");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST_CASE("docs/protocol.md's verb table and the declarations agree: names and usage") {
  auto doc = read_doc();
  REQUIRE_FALSE(doc.empty());
  auto documented = imess::testing::doc_table(doc, "## Client → daemon");
  REQUIRE(documented.size() >= 10);
  std::set<std::string> declared;
  for (const auto& v : verb_table()) {
    INFO(v.name);
    declared.insert(std::string(v.name));
    REQUIRE(documented.count(std::string(v.name)) == 1);
    CHECK(documented[std::string(v.name)].at(0) == usage_args(v));  // the arguments column is the usage
  }
  for (const auto& [name, args] : documented) {
    INFO("documented but not declared: " << name);
    CHECK(declared.count(name) == 1);
  }
}

TEST_CASE("docs/protocol.md's list of verbs open to all is the declarations' Open verbs") {
  auto doc = read_doc();
  auto at = doc.find("* **Open to all**:");
  REQUIRE(at != std::string::npos);
  const std::string line = doc.substr(at, doc.find('\n', at) - at);
  std::set<std::string> listed;
  for (auto open = line.find('`'); open != std::string::npos; open = line.find('`', line.find('`', open + 1) + 1))
    listed.insert(line.substr(open + 1, line.find('`', open + 1) - open - 1));
  std::set<std::string> declared;
  for (const auto& v : verb_table())
    if (v.access == Access::Open) declared.insert(std::string(v.name));
  CHECK(listed == declared);
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
