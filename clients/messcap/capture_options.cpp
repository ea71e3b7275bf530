// messcap's capture command line and --help text. Options take their value as the next
// argument, attached ("-n3") or after '=' ("--count=3").
#include "capture_options.hpp"

#include <charconv>
#include <string_view>

#include "imess/client/usage_error.hpp"
#include "imess/exchange/export_format.hpp"
#include "option_value.hpp"

namespace imess::messcap {
namespace {

using client::UsageError;

int parse_count(std::string_view text) {
  int value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || value < 1 || value > kMaxCount)
    throw UsageError("-n '" + std::string(text) + "': expected a whole number of points, 1.." +
                     std::to_string(kMaxCount) + " (leave -n out to capture until Ctrl-C)");
  return value;
}

}  // namespace

void check_output_file(const std::string& path) {
  try {
    exchange::export_format_for(path);
  } catch (const exchange::FormatError& e) {
    throw UsageError(e.what());
  }
}

bool parse_output_option(OutputOptions& o, int& i, int argc, const char* const argv[]) {
  std::string_view a = argv[i];
  if (a == "--outer") {
    o.outer = true;
  } else if (auto f = option_value("", "--frames", i, argc, argv)) {
    if (f->empty()) throw UsageError("--frames needs a frame store file (JSON, see docs/metrology.md)");
    o.frames_file = std::string(*f);
  } else if (auto n = option_value("", "--frame", i, argc, argv)) {
    if (n->empty()) throw UsageError("--frame needs the name of a frame in the --frames file");
    o.frame = std::string(*n);
  } else if (auto k = option_value("", "--fit", i, argc, argv)) {
    try {
      o.fit = exchange::parse_fit_kind(*k);
    } catch (const exchange::FitKindError& e) {
      throw UsageError(std::string("--fit: ") + e.what());
    }
  } else {
    return false;
  }
  return true;
}

void check_output_options(OutputOptions& o, bool append, bool force) {
  if (o.frame && !o.frames_file) throw UsageError("--frame " + *o.frame + " needs --frames FILE (the frame store)");
  if (o.frames_file && !o.frame) throw UsageError("--frames needs --frame NAME (which frame of the store)");
  if (append && force) throw UsageError("--append and --force exclude each other: continue the file or replace it");
  if ((append || force) && !o.output) throw UsageError(std::string(append ? "--append" : "--force") + " needs -o FILE");
  if (append && !exchange::export_format_for(*o.output).appendable())
    throw UsageError("--append: '" + *o.output + "' is written whole, not line by line; --append works with " +
                     exchange::appendable_extensions() + " (use --force to replace the file, or a new name)");
  o.mode = append ? OpenMode::Append : force ? OpenMode::Overwrite : OpenMode::New;
}

CaptureOptions parse_capture_options(int argc, const char* const argv[]) {
  CaptureOptions o;
  bool have_host = false;
  bool append = false, force = false;
  for (int i = 1; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--append") {
      append = true;
    } else if (a == "--force") {
      force = true;
    } else if (a == "--reconnect") {
      o.reconnect = true;
    } else if (parse_output_option(o.out, i, argc, argv)) {
      continue;
    } else if (auto n = option_value("-n", "--count", i, argc, argv)) {
      o.count = parse_count(*n);
    } else if (auto f = option_value("-o", "--output", i, argc, argv)) {
      if (f->empty()) throw UsageError("-o needs a file name; accepted extensions: " + exchange::accepted_extensions());
      check_output_file(std::string(*f));
      o.out.output = std::string(*f);
    } else if (a.size() > 1 && a.front() == '-') {
      throw UsageError("unknown option '" + std::string(a) +
                       "'; accepted: -n N, -o FILE, --append, --force, --reconnect, --frame NAME, --frames FILE, "
                       "--fit KIND, --outer, --help");
    } else {
      client::take_host_argument(a, o.endpoint, have_host);
    }
  }
  check_output_options(o.out, append, force);
  return o;
}

std::string capture_usage() {
  std::string formats;
  for (const auto& f : exchange::export_formats())
    formats += "                   " + std::string(f.extension) + "  " + std::string(f.description) + "\n";
  return "usage: messcap [HOST[:PORT]] [-n N] [-o FILE] [--append | --force] [--reconnect]\n"
         "               [--frame NAME --frames FILE] [--fit KIND] [--outer]\n"
         "       messcap fit [--surface] KIND [FILE | -]\n"
         "       messcap relate [A B | -]\n"
         "       messcap convert IN OUT [--fit KIND] [--frame NAME --frames FILE]\n"
         "               [--decimals D] [--force] [--outer]\n"
         "       messcap convert REPORT.json [REPORT.json ...] OUT.qif [--force]\n"
         "       messcap inspect PLAN [--points FILE | HOST[:PORT]] [--json OUT] [--html OUT]\n"
         "               [--qif OUT] [--operator NAME] [--feed MM_S]\n"
         "       messcap qualify [HOST[:PORT]] --sphere X,Y,Z --diameter D [--rc FILE]\n"
         "Captures measured points (Hit; MeasPt from a messd without a journal) from messd:\n"
         "prints each as it arrives ('point 1: x y z') and writes it to FILE at once\n"
         "(flushed to disk per point, so Ctrl-C, a closed connection or a crash never lose\n"
         "a point). .xyz/.asc/.hits files keep each point's journal number ('# hit 17');\n"
         ".hits files also each hit's approach direction and tip radius (x y z i j k r),\n"
         "which messcap fit uses to fit probe-compensated (messd must send Hit lines).\n"
         "HOST defaults to localhost, PORT to 1066.\n"
         "\n"
         "  -n, --count N    stop after N points; without -n capture until Ctrl-C\n"
         "                   (SIGINT/SIGTERM) or until messd closes the connection\n"
         "  -o, --output FILE  the format follows the extension (millimetres):\n" +
         formats +
         "                   .csv/.xyz/.asc/.hits grow by the points of each read; the others\n"
         "                   are rewritten whole (temporary file + rename) per read\n"
         "  --append         continue an existing .csv/.xyz/.asc/.hits (default: refuse to\n"
         "                   touch it): first fetch (Replay) every hit after the file's\n"
         "                   last (a .csv needs its 'hit' column: header hit,x,y,z,scan)\n"
         "  --reconnect      when messd goes away, wait for it and fetch what was missed\n"
         "                   (without: exit status 4 when messd goes away)\n"
         "  --force          replace an existing FILE\n"
         "  --frame NAME --frames FILE\n"
         "                   write (and print) the points in frame NAME of the frame\n"
         "                   store FILE (JSON; the frame maps its coordinates to the machine's);\n"
         "                   .hits: the approach directions turned with it\n"
         "  --fit KIND       when the capture ends, fit KIND to all points and print the\n"
         "                   result as one JSON line (also into .json and .dmi files);\n"
         "                   into .hits probe-compensated, as messcap fit fits that file\n"
         "  --outer          DMIS: the fitted feature is outer (a shaft), not inner (a bore)\n"
         "  -h, --help       this text\n"
         "\n"
         "messcap fit [--surface] KIND [FILE | -]: fits KIND to the points of FILE ('x y z'\n"
         "  lines, the NIST .ds layout or messcap's .csv; '-' or none = stdin) and prints one\n"
         "  JSON object. KIND: " + std::string(exchange::kFitKinds) + ".\n"
         "  Lines of 7 numbers 'x y z i j k r' (surface point, unit approach, tip radius:\n"
         "  messd's hits, as messcap -o FILE.hits writes them) are fitted probe-compensated:\n"
         "  plane, circle, sphere, cylinder and cone to the ball centres (xyz - r*ijk),\n"
         "  then offset by r on the material side; --surface fits the surface points x y z\n"
         "  instead.\n"
         "messcap convert IN OUT: reads IN like fit does and writes OUT in the format of\n"
         "  its extension (--decimals D: 0..12, default 6). Hits to a format of plain\n"
         "  points keep their surface points; OUT .hits needs IN of 7-column hits.\n"
         "  OUT .qif: inspection reports (messcap inspect --json; runs of one plan) as\n"
         "  one QIF 3.0 results document, one MeasurementResults per report (docs/qif.md).\n"
         "messcap inspect PLAN: measures (or reads) a part's points and reports every\n"
         "  characteristic of the inspection plan (messcap inspect --help).\n"
         "messcap qualify: touches a reference sphere and sets messd's tip radius and probe\n"
         "  offset from the fit (messcap qualify --help).\n"
         "\n"
         "Exit status: 0 all requested points captured (or, without -n, stopped by\n"
         "Ctrl-C), fit/convert done; 1 messd unreachable, a file error or a failed fit\n"
         "(the message says which points and why); 2 bad arguments; 3 stopped by Ctrl-C\n"
         "before N points arrived; 4 messd went away (without --reconnect) - the points\n"
         "that did arrive are in FILE.\n";
}

}  // namespace imess::messcap
