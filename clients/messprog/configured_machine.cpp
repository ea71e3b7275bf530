// check and plot on the machine of a messd configuration file.
#include "configured_machine.hpp"

#include "imess/client/usage_error.hpp"
#include "imess/core/path_machine.hpp"
#include "imess/net/program_check.hpp"
#include "json_object.hpp"
#include "number_text.hpp"

namespace imess::messprog {

ConfiguredMachine load_configured_machine(const std::string& file) {
  ConfiguredMachine m;
  m.file = file;
  try {
    app::load_json_config(file, m.config);
    app::finish_config(m.config);
  } catch (const app::ConfigError& e) {
    throw client::UsageError("--config " + file + ": " + e.what() + "; accepted: a messd configuration that messd loads (config/*.json)");
  }
  m.machine = core::path_machine(m.config.core);
  m.options = core::path_options(m.config.core);
  if (m.config.backend.rfind("sim-", 0) == 0) {
    planner::Pose p{};
    for (int a = 0; a < m.machine.count; ++a) p[a] = m.config.sim.mechanics.start[a];
    m.start = p;
  }
  return m;
}

programs::Check check_on_configured(const ConfiguredMachine& m, programs::Language lang, const std::string& name,
                                    const std::string& text, const planner::Pose& start,
                                    const programs::SegmentVisitor& visit) {
  net::LoadedProgram p{name, lang, text, {}};
  std::vector<programs::Item> items;
  std::string error;
  if (!net::check_program_for({m.config.server.programs, m.config.core, m.machine, m.options, nullptr}, p, start, items,
                              p.check, error, visit)) {
    programs::Check failed;
    failed.ok = false;
    failed.error = error;
    failed.lines = programs::line_count(text);
    failed.low = failed.high = start;
    return failed;
  }
  return p.check;
}

std::string describe_configured(const ConfiguredMachine& m, const planner::Pose& start) {
  std::string axes, start_text;
  for (int a = 0; a < m.machine.count; ++a) {
    const auto& ax = m.machine.axes[a];
    const std::string unit = ax.kind == planner::AxisKind::Rotary ? "deg" : "mm";
    axes += std::string(a ? ", " : "") + ax.letter + " " + number_text(ax.travel_min) + ".." + number_text(ax.travel_max) + " " +
            number_text(ax.max_velocity) + " " + unit + "/s " + number_text(ax.max_accel) + " " + unit + "/s²";
    start_text += std::string(a ? " " : "") + number_text(start[a]);
  }
  return m.file + " (" + m.config.backend + "): " + axes + ", starting at " + start_text +
         (m.start && *m.start == start ? " (where the simulation powers on)" : "");
}

}  // namespace imess::messprog
