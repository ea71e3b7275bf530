// The offline dry run of check and plot.
#include "dry_run.hpp"

#include <iostream>
#include <stdexcept>

#include "check_report.hpp"
#include "imess/client/usage_error.hpp"
#include "program_file.hpp"

namespace imess::messprog {

OfflineSpec offline_spec(const ProgOptions& options) {
  OfflineSpec spec;
  if (options.axes) spec.letters = *options.axes;
  if (options.travel_min) spec.travel_min = *options.travel_min;
  if (options.travel_max) spec.travel_max = *options.travel_max;
  return spec;
}

DryRun dry_run(const ProgOptions& options, const programs::SegmentVisitor& visit) {
  DryRun d;
  d.machine = offline_machine(options.lang, offline_spec(options));
  d.setup = offline_setup(d.machine);
  const std::string text = read_program(options.file);
  try {
    d.check = programs::check_program(options.lang, text, d.setup, {}, visit);
  } catch (const std::invalid_argument& e) {  // a set-up the language cannot use
    throw client::UsageError(std::string("--axes/--travel do not suit ") + programs::language_name(options.lang) +
                             ": " + e.what());
  }
  return d;
}

int report_program_error(const ProgOptions& options, const programs::Check& check) {
  std::cerr << located_error(options.file, check.error) << "\n";
  return 1;
}

}  // namespace imess::messprog
