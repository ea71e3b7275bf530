// messoffs's run: corrections are applied to a copy, shown before and after, confirmed, and
// only then written; nothing is written when any step fails.
#include "offs_command.hpp"

#include <algorithm>
#include <optional>

#include "confirm.hpp"
#include "design_view.hpp"
#include "gcode_program.hpp"
#include "imess/client/usage_error.hpp"
#include "offset_report.hpp"
#include "table_file.hpp"
#include "table_json.hpp"

namespace imess::messoffs {
namespace {

// The clamping the G-code program is for: --clamping, or the table's only one.
int program_clamping(const OffsOptions& o, const OffsetTable& table) {
  if (o.clamping) return *o.clamping;
  const auto all = table.clampings();
  if (all.size() == 1) return all.front();
  std::string list;
  for (int c : all) list += (list.empty() ? "" : ", ") + std::to_string(c);
  throw client::UsageError("--gcode writes one clamping's offsets and the table has clampings " + list +
                           ": choose one with --clamping N");
}

}  // namespace

int run_offs(const OffsOptions& o, std::ostream& out, std::ostream& err, std::istream& answers, bool interactive) {
  try {
    const OffsetTable table = load_table(o.table);
    if (o.clamping && table.rows.end() == std::find_if(table.rows.begin(), table.rows.end(), [&](const auto& r) {
          return r.clamping == *o.clamping;
        }))
      throw client::UsageError("--clamping " + std::to_string(*o.clamping) + ": no offsets of that clamping in '" +
                               o.table + "'");
    std::optional<DesignChoice> design;
    if (o.frame) design = DesignChoice{*o.frame, load_design_frame(*o.frames, *o.frame)};
    const DesignChoice* view = design ? &*design : nullptr;
    const int gcode_clamping = o.gcode ? program_clamping(o, table) : 0;

    out << "messoffs: " << o.table << "\n";
    print_offsets(out, table, o.clamping, view);

    OffsetTable corrected = table;
    for (const auto& c : o.corrections) {
      OffsetEntry& entry = corrected.find(c.offset, o.clamping);
      const OffsetEntry before = entry;
      const Eigen::Vector3d kept = correction_to_offset_axes(c.typed, entry.offset, view ? &view->frame : nullptr);
      entry.offset.add_correction(kept);
      print_correction(out, before, entry, c.typed, kept, view);
    }
    out << std::flush;

    if (!o.corrections.empty() && !o.yes) {
      if (!interactive) {
        err << "messoffs: not applying the corrections: there is no terminal to confirm them on (stdin is not a "
               "terminal); nothing written. Check the before/after above and add --yes to apply them.\n";
        return client::kExitUsage;
      }
      if (!confirmed(answers, err, "messoffs: apply these corrections and write the output?")) {
        err << "messoffs: corrections not confirmed; nothing written\n";
        return client::kExitFailure;
      }
    }
    // Both outputs are made before either is written, so a bad program leaves no half result.
    std::optional<std::string> program;
    if (o.gcode) program = offset_program(corrected, gcode_clamping, o.table);
    if (o.write_table) {
      write_output_file(*o.write_table, table_to_json(corrected), o.force);
      err << "messoffs: table written to " << *o.write_table << "\n";
    }
    if (program) {
      write_output_file(*o.gcode, *program, o.force);
      err << "messoffs: G10 program for clamping " << gcode_clamping << " written to " << *o.gcode << "\n";
    }
  } catch (const client::UsageError& e) {
    err << "messoffs: " << e.what() << "\n(try messoffs --help)\n";
    return client::kExitUsage;
  } catch (const std::exception& e) {
    err << "messoffs: " << e.what() << "\n";
    return client::kExitFailure;
  }
  return client::kExitOk;
}

}  // namespace imess::messoffs
