// Fuzz target: inspection plan JSON and labelled measured points (text or JSON) -> parsed, then
// the points evaluated against the plan. Only the documented errors may leave: a bad plan or
// point file is an error message, never a crash, a hang or another exception.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "imess/metrology/inspection.hpp"
#include "imess/metrology/inspection_plan.hpp"
#include "imess/metrology/inspection_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imess::metrology;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const InspectionPlan plan = parse_inspection_plan(text, "fuzz.json");
    // The plan's own probe points as hits on the nominal surfaces.
    std::vector<MeasuredPoint> hits;
    for (const auto& f : plan.features)
      for (const auto& p : f.probes) hits.push_back({f.name, plan.placement.point_to_parent(p.point),
                                                     plan.placement.direction_to_parent(p.approach), 1.0});
    (void)evaluate_inspection(plan, hits);
  } catch (const InspectionPlanError&) {
  } catch (const InspectionError&) {
  }
  try {
    (void)parse_measured_points(text, "fuzz.txt");
  } catch (const MeasuredPointsError&) {
  }
  return 0;
}
