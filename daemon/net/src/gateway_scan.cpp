// Scans on the io thread: a MESSD ScanLine / ScanCirc (or an I++ DME scan) as planner requests
// (planner/scan.hpp), checked whole before any is appended, under one id.
#include "imess/net/motion_gateway.hpp"

#include <algorithm>

namespace imess::net {

planner::ScanShape scan_shape(const protocol::ScanLine& c) { return planner::ScanLineShape{c.start, c.end, c.normal}; }

planner::ScanShape scan_shape(const protocol::ScanCircle& c) {
  planner::ScanCircleShape s;
  s.centre = c.centre;
  s.start = c.start;
  s.axis = c.axis;
  s.sweep = c.sweep;
  s.radial = c.bore ? -1 : 1;
  return s;
}

planner::ScanSettings MotionGateway::scan_settings(std::optional<double> speed) const {
  const auto& p = core_.params();
  planner::ScanSettings s;
  s.tip_radius = p.tip_radius;
  s.deflection = p.scan_deflection;
  s.band = p.scan_band;
  s.step = p.scan_step;
  s.speed = speed.value_or(p.scan_speed * p.speed_level);
  s.approach_speed = p.probe_speed;
  s.clearance = std::max(p.prehit_distance, 2.0);
  s.feed = p.goto_speed * p.speed_level;
  const auto& m = planner_.machine();  // an unknown contour's line stays in the travel
  for (int a = 0; a < 3 && a < m.count; ++a) {
    s.travel_min[a] = m.axes[a].travel_min;
    s.travel_max[a] = m.axes[a].travel_max;
  }
  return s;
}

planner::AppendResult MotionGateway::plan_scan(std::uint32_t id, const planner::ScanShape& shape,
                                               const planner::ScanSettings& settings) {
  const auto requests = planner::scan_requests(id, planner_.position(), shape, settings);
  if (!std::holds_alternative<std::vector<planner::Request>>(requests)) return {planner::PlanError::BadScan, id};
  const auto& list = std::get<std::vector<planner::Request>>(requests);
  planner::Planner dry(planner_.machine(), planner_.options());
  dry.set_position(planner_.position());
  for (const auto& r : list)
    if (auto res = dry.append(r); !res.ok()) return res;
  planner::AppendResult res{planner::PlanError::None, id};
  for (const auto& r : list) res = planner_.append(r);
  return res;
}

}  // namespace imess::net
