// messcap qualify: the options, the touches, the computation, Qualify, the messdrc, the report.
#include "qualify_command.hpp"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "imess/client/usage_error.hpp"
#include "messdrc_edit.hpp"
#include "option_value.hpp"
#include "qualify_report.hpp"
#include "qualify_session.hpp"
#include "text_file.hpp"

namespace imess::messcap {
namespace {

using client::UsageError;

struct QualifyOptions {
  client::Endpoint endpoint;
  std::optional<ReferenceSphere> sphere_at;  // the centre, once --sphere is given
  std::optional<double> diameter;
  TouchPattern pattern;
  QualificationLimits limits;
  double feed = 20;
  std::optional<std::string> rc, json_out;
};

std::optional<double> number(std::string_view text) {
  double v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return v;
}

double positive(std::string_view option, std::string_view text, std::string_view what) {
  const auto v = number(text);
  if (!v || !(*v > 0)) throw UsageError(std::string(option) + " '" + std::string(text) + "': expected " + std::string(what));
  return *v;
}

Eigen::Vector3d centre_words(std::string_view text) {
  Eigen::Vector3d c;
  std::string_view rest = text;
  for (int k = 0; k < 3; ++k) {
    const std::size_t comma = rest.find(',');
    const std::string_view word = k < 2 ? rest.substr(0, comma) : rest;
    const auto v = number(word);
    if ((k < 2 && comma == std::string_view::npos) || !v)
      throw UsageError("--sphere '" + std::string(text) + "': expected the nominal centre as X,Y,Z in mm (e.g. 750,650,60)");
    c[k] = *v;
    if (k < 2) rest = rest.substr(comma + 1);
  }
  return c;
}

QualifyOptions parse_options(int argc, const char* const argv[]) {
  QualifyOptions o;
  bool host_seen = false;
  for (int i = 2; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (auto s = option_value("", "--sphere", i, argc, argv)) {
      o.sphere_at = ReferenceSphere{centre_words(*s), 0};
    } else if (auto d = option_value("", "--diameter", i, argc, argv)) {
      o.diameter = positive("--diameter", *d, "the reference sphere's calibrated diameter in mm, above 0");
    } else if (auto n = option_value("", "--points", i, argc, argv)) {
      const auto v = number(*n);
      if (!v || *v != static_cast<int>(*v) || *v < 3 || *v > 72)
        throw UsageError("--points '" + std::string(*n) + "': expected the number of touches on the ring, 3 to 72");
      o.pattern.ring_points = static_cast<int>(*v);
    } else if (auto f = option_value("", "--max-form", i, argc, argv)) {
      o.limits.max_form = positive("--max-form", *f, "the largest form error in mm that still qualifies, above 0");
    } else if (auto f2 = option_value("", "--feed", i, argc, argv)) {
      o.feed = positive("--feed", *f2, "a speed above 0 mm/s");
    } else if (auto r = option_value("", "--rc", i, argc, argv)) {
      if (r->empty()) throw UsageError("--rc needs the stylus's messdrc file");
      o.rc = std::string(*r);
    } else if (auto j = option_value("", "--json", i, argc, argv)) {
      if (j->empty()) throw UsageError("--json needs a file name ('-' for stdout)");
      o.json_out = std::string(*j);
    } else if (a.size() > 1 && a.front() == '-') {
      throw UsageError("qualify: unknown option '" + std::string(a) + "'");
    } else {
      client::take_host_argument(a, o.endpoint, host_seen);
    }
  }
  if (!o.sphere_at) throw UsageError("qualify needs --sphere X,Y,Z: the reference sphere's nominal centre (machine coordinates)");
  if (!o.diameter) throw UsageError("qualify needs --diameter D: the reference sphere's calibrated diameter in mm");
  o.sphere_at->diameter = *o.diameter;
  return o;
}

// The stylus's messdrc with the qualification in it, the other lines as they were.
void write_rc(const std::string& path, const Qualification& q) {
  const bool exists = std::filesystem::exists(path);
  const std::string old =
      exists ? read_text_file(path) : "# messdrc of a stylus (1996 format), written by messcap qualify\n";
  char r[32], x[32], y[32], z[32];
  std::snprintf(r, sizeof r, "%.6f", q.tip_radius);
  std::snprintf(x, sizeof x, "%.6f", q.offset.x());
  std::snprintf(y, sizeof y, "%.6f", q.offset.y());
  std::snprintf(z, sizeof z, "%.6f", q.offset.z());
  const std::vector<RcSetting> settings = {{"TipRadius", r, "mm: effective radius, messcap qualify"},
                                           {"ProbeOffX", x, "mm: probe offset, messcap qualify"},
                                           {"ProbeOffY", y, "mm"},
                                           {"ProbeOffZ", z, "mm"}};
  write_text_file(path, set_messdrc_values(old, settings, path));
}

}  // namespace

std::string qualify_usage() {
  return "usage: messcap qualify [HOST[:PORT]] --sphere X,Y,Z --diameter D [--points N]\n"
         "                       [--rc FILE] [--json OUT] [--max-form MM] [--feed MM_S]\n"
         "Qualifies the probe on a reference sphere: takes control of messd (default\n"
         "localhost:1066), touches the sphere N times on a ring 10 degrees above its equator\n"
         "and once at the pole, fits a sphere to the ball centres and sends messd the\n"
         "effective tip radius (fitted radius - D/2) and the probe offset (the offset in use\n"
         "+ nominal centre - fitted centre) with Qualify (docs/metrology.md).\n"
         "  --sphere X,Y,Z   the sphere's nominal centre, machine coordinates (mm)\n"
         "  --diameter D     the sphere's calibrated diameter (mm)\n"
         "  --points N       touches on the ring, 3 to 72 (default 8)\n"
         "  --rc FILE        also write TipRadius and ProbeOffX/Y/Z into this messdrc (created\n"
         "                   if missing; its other lines and comments are kept)\n"
         "  --json OUT       the report as JSON ('-': stdout, the report then goes to stderr)\n"
         "  --max-form MM    refuse to qualify above this form error (default 0.005)\n"
         "  --feed MM_S      positioning and approach speed (default 20)\n"
         "Exit status: 0 qualified; 1 a connection, probing, fit or file error; 2 bad\n"
         "arguments; 5 refused (form error above --max-form, a radius or an offset messd\n"
         "cannot hold): messd keeps its values, the report is written all the same.\n";
}

int run_qualify_command(int argc, const char* const argv[]) {
  for (int i = 2; i < argc; ++i)
    if (std::string_view(argv[i]) == "-h" || std::string_view(argv[i]) == "--help") {
      std::cout << qualify_usage();
      return client::kExitOk;
    }
  QualifyOptions o;
  try {
    o = parse_options(argc, argv);
    (void)plan_touches(*o.sphere_at, 0, o.pattern);  // the pattern checked before anything moves
  } catch (const std::exception& e) {
    std::cerr << "messcap: " << e.what() << "\n(try messcap qualify --help)\n";
    return client::kExitUsage;
  }
  std::ostream& report = o.json_out && *o.json_out == "-" ? std::cerr : std::cout;
  QualifyReport r{*o.sphere_at, {}, {}, o.limits, std::nullopt};
  try {
    QualifySession session(o.endpoint, std::cerr);
    r.touches = session.touch(r.sphere, o.pattern, o.feed);
    r.result = qualify_probe(r.sphere, r.touches.hits, r.touches.offset);
    r.refused = refusal(r.result, r.limits);
    if (!r.refused) session.qualify(r.result);
    const auto event = session.release();
    print_qualify_report(report, r);
    if (o.json_out) write_text_file(*o.json_out, qualify_json(r));
    if (r.refused) {
      std::cerr << "messcap: qualify: not qualified: " << *r.refused << "; messd keeps its tip radius and offset\n";
      return kExitNotQualified;
    }
    std::cerr << "messcap: messd " << (event ? "says: " + *event : std::string("accepted Qualify")) << "\n";
    if (o.rc) {
      write_rc(*o.rc, r.result);
      std::cerr << "messcap: " << *o.rc << ": TipRadius and ProbeOffX/Y/Z written\n";
    }
    return client::kExitOk;
  } catch (const std::exception& e) {
    std::cerr << "messcap: qualify: " << e.what() << "\n";
    return client::kExitFailure;
  }
}

}  // namespace imess::messcap
