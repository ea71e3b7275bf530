// messprog plot: the planned path of the dry run, drawn; a program error is reported like
// check does and writes nothing.
#include "plot_command.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>

#include "dry_run.hpp"
#include "imess/client/usage_error.hpp"
#include "path_trace.hpp"
#include "plot_geometry.hpp"
#include "program_file.hpp"
#include "svg_plot.hpp"

namespace imess::messprog {

int run_plot_command(const ProgOptions& options) {
  const auto machine = dry_run_machine(options);
  if (machine.count < 2)
    throw client::UsageError((options.config ? "--config " + *options.config + ": the machine has one axis"
                                             : "--axes '" + options.axes.value_or("") + "'") +
                             ": plot draws axes against each other; accepted: two or more axes");
  TraceBuilder trace;
  const DryRun d = dry_run(options, [&](const planner::PlannedSegment& seg, const programs::Item& item) { trace.add(seg, item); });
  if (!d.check.ok) return report_program_error(options, d.check);

  const std::string svg = svg_plot(trace.trace(), d.machine, "messprog plot of " + base_name(options.file));
  std::ofstream out(options.output, std::ios::binary | std::ios::trunc);
  out << svg;
  out.flush();
  if (!out) {
    std::cerr << "messprog: cannot write '" << options.output << "': " << std::strerror(errno) << "\n";
    return 1;
  }
  std::string views;
  for (const auto& v : plot_views(d.machine)) views += (views.empty() ? "" : " and ") + v.title;
  std::cout << "messprog: wrote " << options.output << ": " << views << ", " << d.check.segments << " segments, "
            << trace.trace().probe_targets.size() << " probing moves\n";
  return 0;
}

}  // namespace imess::messprog
