// docs/protocol.md stays true: every verb and every error code of the code is documented.
#include <catch2/catch.hpp>

#include <fstream>
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

TEST_CASE("docs/protocol.md documents every verb with its arguments") {
  auto doc = read_doc();
  REQUIRE_FALSE(doc.empty());
  for (const auto& v : verb_table()) {
    INFO(v.name);
    std::string row = "| `" + std::string(v.name) + "` | " + (v.args.empty() ? "" : "`" + std::string(v.args) + "`");
    CHECK(doc.find(row) != std::string::npos);
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
