// messoffs options: "--opt VALUE" or "--opt=VALUE"; --correct takes two values.
#include "offs_options.hpp"

#include <charconv>
#include <string_view>

#include "correction_spec.hpp"
#include "imess/client/usage_error.hpp"

namespace imess::messoffs {
namespace {

using client::UsageError;

// argv[i] is `name` (value in the next argument) or `name=VALUE`.
std::optional<std::string> value_of(std::string_view name, int& i, int argc, const char* const argv[]) {
  const std::string_view a = argv[i];
  if (a == name) {
    if (i + 1 >= argc) throw UsageError(std::string(name) + " needs a value");
    return std::string(argv[++i]);
  }
  if (a.size() > name.size() && a.substr(0, name.size()) == name && a[name.size()] == '=')
    return std::string(a.substr(name.size() + 1));
  return std::nullopt;
}

int parse_clamping(std::string_view text) {
  int value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || value < 1 || value > 999)
    throw UsageError("--clamping '" + std::string(text) + "': expected a whole number 1..999");
  return value;
}

bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

OffsOptions parse_offs_options(int argc, const char* const argv[]) {
  OffsOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "-h" || a == "--help") {
      o.help = true;
      return o;
    }
    if (a == "--yes" || a == "-y") {
      o.yes = true;
    } else if (a == "--force") {
      o.force = true;
    } else if (a == "--correct") {
      if (i + 2 >= argc)
        throw UsageError("--correct needs OFFSET and AXIS=MM,...: e.g. --correct G512 x=+0.2,z=-0.2");
      const std::string offset = argv[++i];
      const std::string text = argv[++i];
      o.corrections.push_back({offset, parse_correction_spec(text), text});
    } else if (auto v = value_of("--clamping", i, argc, argv)) {
      o.clamping = parse_clamping(*v);
    } else if (auto f = value_of("--frame", i, argc, argv)) {
      o.frame = *f;
    } else if (auto s = value_of("--frames", i, argc, argv)) {
      o.frames = *s;
    } else if (auto w = value_of("--write", i, argc, argv)) {
      if (!ends_with(*w, ".json"))
        throw UsageError("--write '" + *w + "': the table is written as JSON; expected a FILE.json");
      o.write_table = *w;
    } else if (auto g = value_of("--gcode", i, argc, argv)) {
      o.gcode = *g;
    } else if (a.size() > 1 && a.front() == '-') {
      throw UsageError("unknown option '" + std::string(a) +
                       "'; accepted: --clamping N, --frame NAME, --frames FILE, --correct OFFSET AXIS=MM,..., "
                       "--yes, --write FILE.json, --gcode FILE, --force, --help");
    } else if (o.table.empty()) {
      o.table = std::string(a);
    } else {
      throw UsageError("unexpected argument '" + std::string(a) + "' (one TABLE only)");
    }
  }
  if (o.table.empty()) throw UsageError("missing TABLE (a .json or .csv zero-offset table)");
  if (o.frame.has_value() != o.frames.has_value())
    throw UsageError("--frame NAME and --frames FILE go together (the frame NAME of the frame store FILE)");
  if (!o.corrections.empty() && !o.write_table && !o.gcode)
    throw UsageError("--correct needs somewhere to write the result: --write FILE.json and/or --gcode FILE");
  return o;
}

const char* offs_usage() {
  return "usage: messoffs TABLE [--clamping N] [--frame NAME --frames FILE]\n"
         "                [--correct OFFSET AXIS=MM,...]... [--yes] [--write FILE.json] [--gcode FILE] [--force]\n"
         "\n"
         "Shows the work offsets of a 5-axis zero-offset table rotated into their clamping's\n"
         "orientation, p_rot = Rx(-A)*Ry(-B)*(base + correction), and with --frame in a design frame;\n"
         "takes corrections, asks before applying them, and writes the table and a G10 program.\n"
         "\n"
         "  TABLE                 .json or .csv: name, clamping, p, x y z (mm), a b (degrees),\n"
         "                        stored corrections (JSON: \"x\": [base, correction]; CSV: dx, dy, dz)\n"
         "  --clamping N          only clamping N (needed with --gcode when the table has several)\n"
         "  --frame NAME          show offsets and take corrections in the design frame NAME of\n"
         "  --frames FILE         the metrology frame store FILE (a frame maps design -> machine)\n"
         "  --correct OFFSET D    add the correction D, e.g. x=+0.2,z=-0.2 (mm), to OFFSET: in the\n"
         "                        design frame with --frame (a direction: rotation only), else in\n"
         "                        the offset's own axes; repeatable, corrections accumulate\n"
         "  -y, --yes             apply corrections without asking (no terminal: required)\n"
         "  --write FILE.json     write the table with its [base, correction] pairs\n"
         "  --gcode FILE          write the offsets as G10 L2 P<n> X Y Z lines (one clamping)\n"
         "  --force               replace existing output files\n"
         "  -h, --help            this text\n"
         "\n"
         "P numbers: the table's p (1..9, LinuxCNC P1..P9 = G54..G59.3); G54..G59.3 imply theirs.\n"
         "Exit status: 0 done, 1 file error or corrections declined, 2 bad arguments (and\n"
         "corrections with neither a terminal to confirm on nor --yes).\n"
         "Formats and examples: docs/clients.md, examples/offsets/.\n";
}

}  // namespace imess::messoffs
