// The reports of messcap inspect: the terminal table, the JSON document and the self-contained
// HTML page (inline SVG pictures). Formats in docs/metrology.md §17.
#pragma once

#include <ostream>
#include <string>

#include "imess/metrology/inspection.hpp"
#include "imess/metrology/inspection_plan.hpp"

namespace imess::messcap {

struct ReportSource {
  std::string plan;      // the plan file
  std::string measured;  // "measured on messd at HOST:PORT" or "points from FILE"
  std::string time;      // when measured (live) or evaluated (--points), ISO 8601 UTC
  std::string machine;   // "messd at HOST:PORT" when measured live, else empty
  std::string operator_name;  // --operator, may be empty
};

// One line per characteristic: nominal, actual, deviation, tolerance, ok / OUT / --.
void print_inspection_table(std::ostream& out, const metrology::InspectionPlan& plan,
                            const metrology::InspectionResult& result, const ReportSource& source);
std::string inspection_json(const metrology::InspectionPlan& plan, const metrology::InspectionResult& result,
                            const ReportSource& source);
std::string inspection_html(const metrology::InspectionPlan& plan, const metrology::InspectionResult& result,
                            const ReportSource& source);

// Shared by the reports: "ok", "OUT" or "--" (not evaluated), and the tolerance as text
// ("-0.0500/+0.0500", "<= 0.0100") with decimals_for(c) decimals.
std::string verdict_text(const metrology::CharacteristicResult& c);
std::string tolerance_text(const metrology::CharacteristicResult& c);
// Decimals for a characteristic's figures: 4, or more until the printed deviation and limits
// show the verdict (a zone of 0.000104 against 0.0001 prints "0.000104 <= 0.000100 OUT",
// never "0.0001 <= 0.0001 OUT"); at most 9.
int decimals_for(const metrology::CharacteristicResult& c);
// Units of a characteristic's values: "deg" for angles, "mm" otherwise.
const char* unit_of(const metrology::CharacteristicResult& c);

}  // namespace imess::messcap
