// check and plot share this: the machine (the generic one from the options, or with --config
// the configured one), the file read, the program translated and planned on it
// (programs::check_program, or messd's own check on a configured machine).
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
  std::string description;  // the machine, for the report's header
};

OfflineSpec offline_spec(const ProgOptions& options);

// The machine check and plot run on, without the program: the configured one (--config) or
// the generic one; throws client::UsageError naming the option.
planner::Machine dry_run_machine(const ProgOptions& options);

// --from "X,Y,Z": one number per machine axis, within its travel; throws client::UsageError.
planner::Pose start_pose(std::string_view text, const planner::Machine& machine);

// Throws FileError when FILE cannot be read, client::UsageError when the options do not fit
// the program's language. A program error is check.ok == false, not an exception.
DryRun dry_run(const ProgOptions& options, const programs::SegmentVisitor& visit = {});

// Prints a failed check as "FILE:LINE:COL: ..." on stderr; returns the exit status.
int report_program_error(const ProgOptions& options, const programs::Check& check);

}  // namespace imess::messprog
