// docs/ippdme.md stays true: its method table is the declarations (name, queue, arguments),
// its error table the error codes (number, severity, text), both ways.
#include <catch2/catch.hpp>

#include <cstdio>
#include <set>
#include <string>

#include "doc_table.hpp"
#include "imess/ippdme/command_spec.hpp"
#include "imess/ippdme/error_code.hpp"
#include "imess/ippdme/line_framer.hpp"

using namespace imess::ippdme;

TEST_CASE("ippdme docs: the method table is the declarations") {
  const auto doc = imess::testing::read_source_file("docs/ippdme.md");
  REQUIRE_FALSE(doc.empty());
  auto rows = imess::testing::doc_table(doc, "## Methods");
  std::set<std::string> declared;
  for (const auto& spec : command_table()) {
    const std::string name(spec.name);
    INFO(name);
    declared.insert(name);
    REQUIRE(rows.count(name) == 1);
    REQUIRE(rows[name].size() >= 2);
    CHECK(rows[name][0] == (spec.queue == Queue::Fast ? "fast (E tag)" : "normal"));
    CHECK(rows[name][1] == (spec.shape == Shape::NotImplemented ? std::string("0501") : "(" + std::string(spec.usage) + ")"));
  }
  for (const auto& [name, cells] : rows) {
    INFO("documented, not declared: " << name);
    CHECK(declared.count(name) == 1);
  }
}

TEST_CASE("ippdme docs: the error table is the error codes") {
  const auto doc = imess::testing::read_source_file("docs/ippdme.md");
  auto rows = imess::testing::doc_table(doc, "## Error numbers");
  CHECK(rows.size() == error_table().size());
  for (const auto& e : error_table()) {
    char number[8];
    std::snprintf(number, sizeof number, "%04d", number_of(e.code));
    INFO(number);
    REQUIRE(rows.count(number) == 1);
    REQUIRE(rows[number].size() >= 2);
    CHECK(rows[number][0] == std::to_string(severity_number(e.severity)));
    CHECK(rows[number][1] == e.text);
  }
  CHECK(doc.find("up to " + std::to_string(kMaxLineLength) + " characters") != std::string::npos);
}
