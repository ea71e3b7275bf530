// The runtime parameter table behind Get and Set: names, units, accepted ranges.
#pragma once
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "imess/core/core_types.hpp"

namespace imess::net {

struct ParamSpec {
  std::string_view name;
  std::string_view unit;
  double min, max;
  std::optional<core::ParamId> core_id;  // set through the motion loop; empty: net-side
  bool read_only;
  std::string_view help;
};

std::span<const ParamSpec> param_table();
const ParamSpec* find_param(std::string_view name);  // case-insensitive

// Parses a Set value for spec; on failure returns a message saying what is accepted.
std::optional<double> parse_param_value(const ParamSpec& spec, std::string_view text, std::string& error);

}  // namespace imess::net
