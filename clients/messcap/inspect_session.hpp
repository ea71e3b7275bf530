// messcap inspect, live: takes control of messd, measures every feature's probe points with
// Probe cycles (alignment features first, by the plan's placement; the rest in the part frame
// they give), and returns the hits labelled by feature.
#pragma once

#include <optional>
#include <ostream>
#include <vector>

#include "imess/client/endpoint.hpp"
#include "imess/metrology/inspection.hpp"
#include "imess/metrology/inspection_plan.hpp"
#include "machine_link.hpp"

namespace imess::messcap {

struct LiveOptions {
  client::Endpoint endpoint;
  std::optional<double> feed;  // overrides the plan's probing.feed
};

// Progress goes to `log` (one line per feature). Throws MachineError (machine_link.hpp), or
// metrology::InspectionError when the alignment features give no part frame.
std::vector<metrology::MeasuredPoint> measure_live(const metrology::InspectionPlan& plan, const LiveOptions& options,
                                                   std::ostream& log);

// Tells messd the run's result (Verdict part in out pass|fail), which it passes on to every
// client as the Inspected event (the MQTT bridge publishes it): on a connection of its own, after the evaluation. A
// messd that does not know the verb (older), or refuses it, is only noted in `log`.
void announce_result(const metrology::InspectionPlan& plan, const metrology::InspectionResult& result,
                     const LiveOptions& options, std::ostream& log);

// The order features are measured in: the alignment's three first, then the plan's order.
std::vector<const metrology::PlanFeature*> measuring_order(const metrology::InspectionPlan& plan);

}  // namespace imess::messcap
