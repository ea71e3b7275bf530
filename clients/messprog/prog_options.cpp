// messprog's command line. Options take their value as the next argument or after '='
// ("--lang gcode", "--lang=gcode"; "-o x.svg", "-ox.svg").
#include "prog_options.hpp"

#include <charconv>
#include <string_view>

#include "imess/client/usage_error.hpp"
#include "program_file.hpp"

namespace imess::messprog {
namespace {

using client::UsageError;

const char* command_name(Command c) {
  switch (c) {
    case Command::Check: return "check";
    case Command::Plot: return "plot";
    case Command::Run: return "run";
  }
  return "?";
}

const char* accepted_options(Command c) {
  switch (c) {
    case Command::Check: return "--canon, --config FILE, --from X,Y,Z, --lang L, --axes LETTERS, --travel MIN:MAX, --help";
    case Command::Plot: return "-o OUT.svg, --config FILE, --from X,Y,Z, --lang L, --axes LETTERS, --travel MIN:MAX, --help";
    case Command::Run: return "--detached, --lang L, --help";
  }
  return "";
}

// The value of option `name` (long "--x" or short "-o") at argv[i], in any of its spellings;
// advances i past a separate value. nullopt when argv[i] is another option.
std::optional<std::string_view> value_of(std::string_view name, int& i, int argc, const char* const argv[]) {
  const std::string_view a = argv[i];
  if (a == name) {
    if (i + 1 >= argc) throw UsageError(std::string(name) + " needs a value");
    return std::string_view(argv[++i]);
  }
  const bool is_long = name.size() > 2;
  if (a.size() > name.size() && a.substr(0, name.size()) == name) {
    if (!is_long) return a.substr(name.size());
    if (a[name.size()] == '=') return a.substr(name.size() + 1);
  }
  return std::nullopt;
}

double travel_number(std::string_view text, std::string_view whole) {
  double v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size())
    throw UsageError("--travel '" + std::string(whole) +
                     "': accepted MIN:MAX, two numbers with MIN < MAX (mm, degrees for rotary axes), e.g. -500:500");
  return v;
}

bool ends_with_svg(std::string_view path) {
  if (path.size() < 4) return false;
  std::string ext(path.substr(path.size() - 4));
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".svg";
}

}  // namespace

ProgOptions parse_prog_options(int argc, const char* const argv[]) {
  ProgOptions o;
  if (argc < 2) throw UsageError("a command is needed; accepted: check, plot, run");
  const std::string_view command = argv[1];
  if (command == "-h" || command == "--help") {
    o.help = true;
    return o;
  }
  if (command == "check") o.command = Command::Check;
  else if (command == "plot") o.command = Command::Plot;
  else if (command == "run") o.command = Command::Run;
  else throw UsageError("unknown command '" + std::string(command) + "'; accepted: check, plot, run");

  const std::string cmd = command_name(o.command);
  const bool offline = o.command != Command::Run;
  std::optional<programs::Language> lang;
  bool have_file = false, have_host = false;
  for (int i = 2; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "-h" || a == "--help") {
      o.help = true;
      return o;
    }
    if (auto v = value_of("--lang", i, argc, argv)) {
      lang = programs::language_named(*v);
      if (!lang) throw UsageError("--lang '" + std::string(*v) + "': accepted gcode, hpgl, mrm");
    } else if (auto axes = offline ? value_of("--axes", i, argc, argv) : std::nullopt) {
      o.axes = std::string(*axes);
    } else if (auto t = offline ? value_of("--travel", i, argc, argv) : std::nullopt) {
      const auto colon = t->find(':', 1);  // "-500:500": the first character may be a sign
      if (colon == std::string_view::npos)
        throw UsageError("--travel '" + std::string(*t) +
                         "': accepted MIN:MAX, two numbers with MIN < MAX (mm, degrees for rotary axes), e.g. -500:500");
      o.travel_min = travel_number(t->substr(0, colon), *t);
      o.travel_max = travel_number(t->substr(colon + 1), *t);
      if (!(*o.travel_min < *o.travel_max))
        throw UsageError("--travel '" + std::string(*t) + "': MIN must be below MAX, e.g. -500:500");
    } else if (auto from = offline ? value_of("--from", i, argc, argv) : std::nullopt) {
      o.from = std::string(*from);
    } else if (auto config = offline ? value_of("--config", i, argc, argv) : std::nullopt) {
      o.config = std::string(*config);
    } else if (a == "--canon" && o.command == Command::Check) {
      o.canon = true;
    } else if (auto out = o.command == Command::Plot ? value_of("-o", i, argc, argv) : std::nullopt) {
      o.output = std::string(*out);
    } else if (auto out2 = o.command == Command::Plot ? value_of("--output", i, argc, argv) : std::nullopt) {
      o.output = std::string(*out2);
    } else if (a == "--detached" && o.command == Command::Run) {
      o.detached = true;
    } else if (a.size() > 1 && a.front() == '-') {
      throw UsageError("unknown option '" + std::string(a) + "' for " + cmd + "; accepted: " + accepted_options(o.command));
    } else if (!have_file) {
      o.file = std::string(a);
      have_file = true;
    } else if (o.command == Command::Run) {
      client::take_host_argument(a, o.endpoint, have_host);
    } else {
      throw UsageError("unexpected argument '" + std::string(a) + "'; " + cmd + " takes one program FILE");
    }
  }
  if (o.config && (o.axes || o.travel_min))
    throw UsageError(std::string(o.axes ? "--axes" : "--travel") + " with --config " + *o.config +
                     ": the configuration gives the axes and their travel; accepted: one of them");
  if (!have_file)
    throw UsageError(cmd + " needs a program FILE (" + programs::kExtensions + ", or another name with --lang)");
  if (o.command == Command::Plot) {
    if (o.output.empty()) throw UsageError("plot needs -o OUT.svg, the file to write");
    if (!ends_with_svg(o.output))
      throw UsageError("-o '" + o.output + "': the plot is an SVG drawing; accepted: a file name ending in .svg");
  }
  o.lang = language_for(o.file, lang);
  return o;
}

std::string prog_usage() {
  return "usage: messprog check FILE [--canon] [--config FILE | --axes LETTERS --travel MIN:MAX] [--from X,Y,Z] [--lang L]\n"
         "       messprog plot FILE -o OUT.svg [--config FILE | --axes LETTERS --travel MIN:MAX] [--from X,Y,Z] [--lang L]\n"
         "       messprog run FILE [HOST[:PORT]] [--detached] [--lang L]\n"
         "Checks, draws and runs G-code, HPGL and MRM programs. The language follows FILE's\n"
         "extension: .nc .ngc .gcode .tap G-code, .plt .hpgl HPGL, .mrm MRM; or --lang.\n"
         "\n"
         "check   translates FILE and plans every move on a generic machine, offline:\n"
         "        prints lines, blocks, segments, the path length (feed, rapid, probe),\n"
         "        the estimated time (from the planner's profiles, not a measurement) and\n"
         "        the bounding box of every axis, and the G-code accepted without effect\n"
         "        (G40 G49 G64 ...: states IMESS is always in) or skipped (block delete '/').\n"
         "        An error prints FILE:LINE:COL: message.\n"
         "plot    draws the planned path as SVG, two views side by side: X-Y (top) and\n"
         "        X-Z (front; without Z the third axis, e.g. C of the MRM arm). Feed moves\n"
         "        solid, rapids dashed, probing moves in green with a circle at each target.\n"
         "run     sends FILE to messd (Upload), lets messd check it against the real machine\n"
         "        and runs it (Run), showing the block and line being executed.\n"
         "        Ctrl-C pauses and asks 'abort or resume? [a/r]' (when stdin is a\n"
         "        terminal; otherwise Ctrl-C aborts). HOST defaults to localhost, PORT to 1066.\n"
         "\n"
         "  --canon          check: print the program's motion as LinuxCNC's rs274 -g prints\n"
         "                   its canonical calls (STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED,\n"
         "                   STRAIGHT_PROBE, DWELL; program units), to diff against LinuxCNC\n"
         "  --config FILE    check/plot: the machine of a messd configuration (its axes,\n"
         "                   travel, speeds, the programs section, a simulation's start) and\n"
         "                   messd's own check: what passes here, messd's Load accepts\n"
         "  --from X,Y,Z     check/plot: where the machine starts, one number per axis in its\n"
         "                   order (default: the configured simulation's start, else 0)\n"
         "  --lang L         gcode, hpgl or mrm, whatever the extension\n"
         "  --axes LETTERS   check/plot: the machine's axes, 1-9 of X Y Z A B C U V W\n"
         "                   (default XYZ; MRM: XYCUV, its A B C words moving U V C)\n"
         "  --travel MIN:MAX check/plot: every axis' travel (default -1000:1000, mm or\n"
         "                   degrees); the generic machine: 100 mm/s, 1000 mm/s² per axis\n"
         "  -o, --output OUT.svg  plot: the drawing to write\n"
         "  --detached       run: the program goes on in messd if messprog goes away\n"
         "                   (by default messd stops it when the connection closes)\n"
         "  -h, --help       this text\n"
         "\n"
         "Exit status: 0 check passed, plot written, or the program ended ok; 1 the program\n"
         "has an error, a file cannot be read or written, messd cannot be reached or\n"
         "refused the program, the program failed or was aborted, or the connection was\n"
         "lost; 2 bad arguments.\n";
}

}  // namespace imess::messprog
