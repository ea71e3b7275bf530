// What messprog check prints: the figures of a passed check, and an error the way compilers
// print one, "FILE:LINE:COL: kind: found ..., accepted ...".
#pragma once
#include <string>
#include <string_view>

#include "imess/planner/axes.hpp"
#include "imess/programs/check.hpp"

namespace imess::messprog {

// "part.nc:3:7: unsupported code: found G81, accepted ..." from the library's
// "line 3:7: unsupported code: ..."; a message without a line gets "part.nc: ".
std::string located_error(std::string_view file, std::string_view message);

// The report of a check that passed (several lines, each ending in '\n'). `machine_text`
// describes the machine the figures hold for.
std::string check_report(std::string_view file, programs::Language lang, const programs::Check& check,
                         const planner::Machine& machine, std::string_view machine_text);

// 12.345 s as "12.35 s", 3725 s as "3725.00 s (1:02:05)".
std::string duration_text(double seconds);

}  // namespace imess::messprog
