// The core's parameter table (core_params.hpp): every row reaches its own CoreParams field,
// with that field's default, and its wire name is its own.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "imess/core/core_params.hpp"

using namespace imess::core;

TEST_CASE("core parameter table: row i is ParamId i, param_ref reaches the row's field, defaults agree") {
  const CoreParams defaults;
  for (std::size_t i = 0; i < kCoreParams.size(); ++i) {
    const CoreParamSpec& row = kCoreParams[i];
    INFO(row.name);
    CHECK(static_cast<std::size_t>(row.id) == i);
    CHECK(param_value(defaults, row.id) == defaults.*row.field);
    CHECK(row.initial() == defaults.*row.field);
    CHECK(row.min <= row.initial());
    CHECK(row.initial() <= row.max);
    CoreParams p;
    param_ref(p, row.id) = 1234.5;
    CHECK(p.*row.field == 1234.5);
    for (const auto& other : kCoreParams)  // only that field changed
      if (other.id != row.id) CHECK(p.*other.field == defaults.*other.field);
  }
}

TEST_CASE("core parameter table: wire names and configuration keys are unique") {
  std::set<std::string> names, keys;
  for (const auto& row : kCoreParams) {
    std::string lower;
    for (char c : row.name) lower += static_cast<char>(c | 0x20);
    CHECK(names.insert(lower).second);
    CHECK(keys.insert(std::string(row.config)).second);
    CHECK(row.config.substr(0, 7) == "motion.");
  }
}
