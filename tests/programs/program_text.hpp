// Test helpers: a translation as lines of text (describe), or its error message; run and err
// for G-code (the HPGL and MRM tests name theirs hpgl and mrm).
#pragma once
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "imess/programs/gcode.hpp"
#include "imess/programs/program.hpp"

namespace imess::programs::test {

inline std::vector<std::string> lines(const Translation& t, const planner::Machine& m) {
  INFO(t.error.message());
  REQUIRE(t.ok);
  std::vector<std::string> out;
  for (const auto& it : t.items) out.push_back(describe(it, m));
  return out;
}

inline std::string error_text(const Translation& t) {
  REQUIRE_FALSE(t.ok);
  CHECK(t.items.empty());
  return t.error.message();
}

using Lines = std::vector<std::string>;

inline Lines run(const char* text, const GcodeOptions& o = {}) { return lines(translate_gcode(text, o), o.machine); }
inline std::string err(const char* text, const GcodeOptions& o = {}) { return error_text(translate_gcode(text, o)); }

}  // namespace imess::programs::test
