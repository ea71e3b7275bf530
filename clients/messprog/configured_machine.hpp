// The machine a messd configuration file describes, for check and plot with --config FILE:
// its axes, travel and limits, the programs section (G28/G30 poses, the outputs M3/M7/M8/M62
// switch, the HPGL pen, the MRM axes) and, on a simulated backend, where it starts. The
// program is then checked by messd's own function (net::check_program_for), so what
// `messprog check --config` accepts, messd's Load accepts on that machine (the part frames
// G54 ... G59.3 messd keeps are not read: offsets start at zero, as on a new machine).
#pragma once
#include <optional>
#include <string>

#include "imess/programs/check.hpp"
#include "config.hpp"

namespace imess::messprog {

struct ConfiguredMachine {
  std::string file;
  app::DaemonConfig config;            // as messd reads it (limits resolved)
  planner::Machine machine;            // the planner's view of it, as messd builds it
  planner::PlannerOptions options;
  std::optional<planner::Pose> start;  // a simulated backend's power-on position; real machines: unknown
};

// Reads FILE as messd does; throws client::UsageError "--config FILE: <what is wrong>".
ConfiguredMachine load_configured_machine(const std::string& file);

// Translates and checks the program text on it from `start`, as messd's Load would.
programs::Check check_on_configured(const ConfiguredMachine& m, programs::Language lang, const std::string& name,
                                    const std::string& text, const planner::Pose& start,
                                    const programs::SegmentVisitor& visit = {});

// "config/sim-servo-card.json (sim-servo-card): axes XYZ, travel X 0..860 Y 0..660 Z 0..350, 200 mm/s, ..."
std::string describe_configured(const ConfiguredMachine& m, const planner::Pose& start);

}  // namespace imess::messprog
