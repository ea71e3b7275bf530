// messcap's command line and --help text. Options take their value as the next argument,
// attached ("-n3") or after '=' ("--count=3").
#include "capture_options.hpp"

#include <charconv>
#include <string_view>

#include "imess/client/usage_error.hpp"

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

// Matches an option with a value in any of its spellings; advances i past a separate value.
std::optional<std::string_view> value_of(std::string_view shortname, std::string_view longname, int& i,
                                         int argc, const char* const argv[]) {
  std::string_view a = argv[i];
  std::string_view name;
  std::optional<std::string_view> attached;
  if (a == shortname || a == longname) {
    name = a;
  } else if (a.size() > shortname.size() && a.substr(0, shortname.size()) == shortname) {
    attached = a.substr(shortname.size());
  } else if (a.size() > longname.size() && a.substr(0, longname.size() + 1) == std::string(longname) + "=") {
    attached = a.substr(longname.size() + 1);
  } else {
    return std::nullopt;
  }
  if (attached) return attached;
  if (i + 1 >= argc) throw UsageError(std::string(name) + " needs a value (see messcap --help)");
  return std::string_view(argv[++i]);
}

}  // namespace

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
    } else if (auto n = value_of("-n", "--count", i, argc, argv)) {
      o.count = parse_count(*n);
    } else if (auto f = value_of("-o", "--output", i, argc, argv)) {
      if (f->empty()) throw UsageError("-o needs a file name ending in .csv or .xyz");
      format_for_path(*f);
      o.output = std::string(*f);
    } else if (a.size() > 1 && a.front() == '-') {
      throw UsageError("unknown option '" + std::string(a) +
                       "'; accepted: -n N, -o FILE, --append, --force, --help");
    } else if (have_host) {
      throw UsageError("unexpected argument '" + std::string(a) + "'; expected a single HOST[:PORT]");
    } else {
      o.endpoint = client::parse_endpoint(a);
      have_host = true;
    }
  }
  if (append && force) throw UsageError("--append and --force exclude each other: continue the file or replace it");
  if ((append || force) && !o.output) throw UsageError(std::string(append ? "--append" : "--force") + " needs -o FILE");
  o.mode = append ? OpenMode::Append : force ? OpenMode::Overwrite : OpenMode::New;
  return o;
}

std::string capture_usage() {
  return "usage: messcap [HOST[:PORT]] [-n N] [-o FILE] [--append | --force]\n"
         "Captures measured points (MeasPt) from messd: prints each as it arrives\n"
         "('point 1: x y z') and writes it to FILE at once (flushed to disk per point,\n"
         "so Ctrl-C, a closed connection or a crash never lose a point).\n"
         "HOST defaults to localhost, PORT to 1066.\n"
         "\n"
         "  -n, --count N    stop after N points; without -n capture until Ctrl-C\n"
         "                   (SIGINT/SIGTERM) or until messd closes the connection\n"
         "  -o, --output FILE\n"
         "                   FILE.csv: header 'x,y,z', then one 'x,y,z' line per point\n"
         "                   FILE.xyz: one 'x y z' line per point (no header)\n"
         "                   millimetres with 3 decimals, exactly as messd sent them\n"
         "  --append         continue an existing FILE (default: refuse to touch it)\n"
         "  --force          replace an existing FILE\n"
         "  -h, --help       this text\n"
         "\n"
         "Exit status: 0 all requested points captured (or, without -n, stopped by\n"
         "Ctrl-C or by messd closing the connection); 1 messd unreachable or a file\n"
         "error; 2 bad arguments; 3 stopped (Ctrl-C, connection closed) before N points\n"
         "arrived - the points that did arrive are in FILE.\n";
}

}  // namespace imess::messcap
