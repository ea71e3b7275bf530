// check and plot share this: the generic machine from the options, the file read, the
// program translated and planned on it (programs::check_program).
#pragma once
#include <string>

#include "imess/programs/check.hpp"
#include "offline_machine.hpp"
#include "prog_options.hpp"

namespace imess::messprog {

struct DryRun {
  planner::Machine machine;
  programs::Setup setup;
  programs::Check check;
};

OfflineSpec offline_spec(const ProgOptions& options);

// --from "X,Y,Z": one number per machine axis, within its travel; throws client::UsageError.
planner::Pose start_pose(std::string_view text, const planner::Machine& machine);

// Throws FileError when FILE cannot be read, client::UsageError when the options do not fit
// the program's language. A program error is check.ok == false, not an exception.
DryRun dry_run(const ProgOptions& options, const programs::SegmentVisitor& visit = {});

// Prints a failed check as "FILE:LINE:COL: ..." on stderr; returns the exit status.
int report_program_error(const ProgOptions& options, const programs::Check& check);

}  // namespace imess::messprog
