// The check before a program runs: one function for messd and messprog check --config.
#include "imess/net/program_check.hpp"

#include "imess/net/part_frames.hpp"

namespace imess::net {

bool check_program_for(const MachineForPrograms& m, const LoadedProgram& p, const planner::Pose& start,
                       std::vector<programs::Item>& items, programs::Check& check, std::string& error,
                       const programs::SegmentVisitor& visit) {
  programs::Setup setup = program_setup(m.programs, m.core, m.machine, start);
  if (m.frames && !work_offsets_from_frames(*m.frames, m.core.layout, setup.gcode, error)) return false;
  programs::Translation t;
  try {
    t = programs::translate(p.lang, p.text, setup);
  } catch (const std::invalid_argument& e) {
    // A translator refuses this machine as its set-up (docs/programs.md: e.g. HPGL with a Z
    // pen on a machine without Z). Uncaught, this left the io handler and ended messd — an
    // Upload or a Load of any .plt on config/sim-mrm-arm.json did (found by
    // tests/golden/test_program_properties.cpp). It is a program this machine cannot run.
    error = std::string("line 1:1: not configured: found a ") + programs::language_name(p.lang) +
            " program, which this machine cannot run (" + e.what() + "), accepted programs in a language its axes and the programs section allow";
    return false;
  }
  if (!t.ok) {
    error = t.error.message();
    return false;
  }
  if (!resolve_program_outputs(t.items, m.programs, m.core, error)) return false;
  if (!offset_writes_storable(t.offset_writes, m.core.layout, error)) return false;
  check = programs::check_items(t.items, setup.machine, m.options, start, 0, visit);
  check.lines = programs::line_count(p.text);
  check.notes = std::move(t.notes);
  check.offset_writes = std::move(t.offset_writes);
  if (!check.ok) {
    error = check.error;
    return false;
  }
  items = std::move(t.items);
  return true;
}

}  // namespace imess::net
