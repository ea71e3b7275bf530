// The check a program passes before messd runs it (Load, Upload, Run): translated with the
// configuration's set-up for this machine (programs section, stored work offsets G54 ...
// G59.3), its outputs resolved to the machine's, and every segment planned within the
// machine's limits. One function, so `messprog check --config` answers what messd's Load does.
#pragma once
#include <string>
#include <vector>

#include "imess/core/core_types.hpp"
#include "imess/net/program_run.hpp"
#include "imess/planner/planner.hpp"

namespace imess::net {

class PartFrames;

struct MachineForPrograms {
  const ProgramConfig& programs;
  const core::CoreConfig& core;          // resolved limits (core::resolved_limits)
  const planner::Machine& machine;       // core::path_machine of it
  const planner::PlannerOptions& options;
  const PartFrames* frames = nullptr;    // the stored frames G54 ... G59.3; null: none stored
};

// Translates and checks `p` from `start`; the items of the run in `items`. False with `error`
// ("line L:C: ..." as Err 213 carries it) when the program cannot run on this machine.
// `visit`, when given, sees every planned segment (messprog plot).
bool check_program_for(const MachineForPrograms& m, const LoadedProgram& p, const planner::Pose& start,
                       std::vector<programs::Item>& items, programs::Check& check, std::string& error,
                       const programs::SegmentVisitor& visit = {});

}  // namespace imess::net
