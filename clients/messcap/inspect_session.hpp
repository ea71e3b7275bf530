// messcap inspect, live: takes control of messd, measures every feature's probe points with
// Probe cycles (alignment features first, by the plan's placement; the rest in the part frame
// they give), and returns the hits labelled by feature.
#pragma once

#include <optional>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "imess/client/endpoint.hpp"
#include "imess/metrology/inspection.hpp"
#include "imess/metrology/inspection_plan.hpp"

namespace imess::messcap {

// messd unreachable, a refused command, a failed probe: the message says which and why.
class InspectSessionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LiveOptions {
  client::Endpoint endpoint;
  std::optional<double> feed;  // overrides the plan's probing.feed
};

// Progress goes to `log` (one line per feature). Throws InspectSessionError, or
// metrology::InspectionError when the alignment features give no part frame.
std::vector<metrology::MeasuredPoint> measure_live(const metrology::InspectionPlan& plan, const LiveOptions& options,
                                                   std::ostream& log);

// The order features are measured in: the alignment's three first, then the plan's order.
std::vector<const metrology::PlanFeature*> measuring_order(const metrology::InspectionPlan& plan);

}  // namespace imess::messcap
