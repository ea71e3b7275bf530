// The offline dry run of check and plot.
#include "dry_run.hpp"

#include <algorithm>
#include <charconv>
#include <iostream>
#include <stdexcept>

#include "check_report.hpp"
#include "configured_machine.hpp"
#include "imess/net/program_run.hpp"
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

planner::Pose start_pose(std::string_view text, const planner::Machine& m) {
  const std::string accepted = "; accepted X,Y,Z...: one number per axis of the machine (" + std::to_string(m.count) +
                               "), each within its travel, e.g. --from 430,330,100";
  planner::Pose p{};
  std::size_t at = 0;
  for (int i = 0; i < m.count; ++i) {
    const std::size_t comma = i + 1 < m.count ? text.find(',', at) : text.size();
    const std::string_view part = comma == std::string_view::npos ? text.substr(at) : text.substr(at, comma - at);
    double v = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (part.empty() || ec != std::errc{} || end != part.data() + part.size() || comma == std::string_view::npos)
      throw client::UsageError("--from '" + std::string(text) + "'" + accepted);
    if (v < m.axes[i].travel_min || v > m.axes[i].travel_max)
      throw client::UsageError("--from '" + std::string(text) + "': " + m.axes[i].letter + " outside its travel" + accepted);
    p[i] = v;
    at = comma + 1;
  }
  return p;
}

namespace {

// The start when --from is not given: the configured machine's (simulated: its power-on
// position), else 0 on every axis or the travel end nearest to it.
planner::Pose default_start(const planner::Machine& m) {
  planner::Pose p{};
  for (int i = 0; i < m.count; ++i) p[i] = std::clamp(0.0, m.axes[i].travel_min, m.axes[i].travel_max);
  return p;
}

DryRun configured_dry_run(const ProgOptions& options, const programs::SegmentVisitor& visit) {
  const ConfiguredMachine cm = load_configured_machine(*options.config);
  DryRun d;
  d.machine = cm.machine;
  const planner::Pose start = options.from ? start_pose(*options.from, d.machine) : cm.start.value_or(default_start(d.machine));
  d.setup = net::program_setup(cm.config.server.programs, cm.config.core, cm.machine, start);
  d.check = check_on_configured(cm, options.lang, base_name(options.file), read_program(options.file), start, visit);
  d.description = describe_configured(cm, start);
  return d;
}

}  // namespace

planner::Machine dry_run_machine(const ProgOptions& options) {
  if (options.config) return load_configured_machine(*options.config).machine;
  return offline_machine(options.lang, offline_spec(options));
}

DryRun dry_run(const ProgOptions& options, const programs::SegmentVisitor& visit) {
  if (options.config) return configured_dry_run(options, visit);
  DryRun d;
  d.machine = offline_machine(options.lang, offline_spec(options));
  d.setup = offline_setup(d.machine);
  if (options.from) d.setup.start = start_pose(*options.from, d.machine);
  const std::string text = read_program(options.file);
  try {
    d.check = programs::check_program(options.lang, text, d.setup, {}, visit);
  } catch (const std::invalid_argument& e) {  // a set-up the language cannot use
    throw client::UsageError(std::string("--axes/--travel do not suit ") + programs::language_name(options.lang) +
                             ": " + e.what());
  }
  d.description = describe_machine(d.machine, d.setup);
  return d;
}

int report_program_error(const ProgOptions& options, const programs::Check& check) {
  std::cerr << located_error(options.file, check.error) << "\n";
  return 1;
}

}  // namespace imess::messprog
