// messcap inspect: the plan, the points (from a file or measured live), the evaluation, the
// table on the terminal and the JSON / HTML reports, and the QIF document written from the JSON.
#include "inspect_command.hpp"

#include <charconv>
#include <iostream>
#include <optional>

#include "imess/client/usage_error.hpp"
#include "imess/metrology/inspection_points.hpp"
#include "inspect_report.hpp"
#include "inspect_session.hpp"
#include "option_value.hpp"
#include "qif_document.hpp"
#include "text_file.hpp"

namespace imess::messcap {
namespace {

using client::UsageError;

struct InspectOptions {
  std::string plan;
  std::optional<std::string> points_file;
  std::optional<client::Endpoint> endpoint;
  std::optional<std::string> json_out, html_out, qif_out;
  std::string operator_name;
  std::optional<double> feed;
};

InspectOptions parse_options(int argc, const char* const argv[]) {
  InspectOptions o;
  bool host_seen = false;
  client::Endpoint endpoint;
  for (int i = 2; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (auto v = option_value("", "--points", i, argc, argv)) {
      if (v->empty()) throw UsageError("--points needs a file of measured points (FEATURE x y z [i j k r] lines or a report)");
      o.points_file = std::string(*v);
    } else if (auto j = option_value("", "--json", i, argc, argv)) {
      if (j->empty()) throw UsageError("--json needs a file name ('-' for stdout)");
      o.json_out = std::string(*j);
    } else if (auto h = option_value("", "--html", i, argc, argv)) {
      if (h->empty()) throw UsageError("--html needs a file name");
      o.html_out = std::string(*h);
    } else if (auto q = option_value("", "--qif", i, argc, argv)) {
      if (q->empty()) throw UsageError("--qif needs a file name ('-' for stdout)");
      o.qif_out = std::string(*q);
    } else if (auto op = option_value("", "--operator", i, argc, argv)) {
      if (op->empty()) throw UsageError("--operator needs a name (recorded in the reports)");
      o.operator_name = std::string(*op);
    } else if (auto f = option_value("", "--feed", i, argc, argv)) {
      double feed = 0;
      auto [end, ec] = std::from_chars(f->data(), f->data() + f->size(), feed);
      if (f->empty() || ec != std::errc{} || end != f->data() + f->size() || !(feed > 0))
        throw UsageError("--feed '" + std::string(*f) + "': expected a speed above 0 mm/s");
      o.feed = feed;
    } else if (a.size() > 1 && a.front() == '-') {
      throw UsageError("inspect: unknown option '" + std::string(a) + "'; usage: " + inspect_usage().substr(7, 80));
    } else if (o.plan.empty()) {
      o.plan = std::string(a);
    } else {
      client::take_host_argument(a, endpoint, host_seen);
    }
  }
  if (o.plan.empty()) throw UsageError("inspect needs a PLAN file (JSON, see docs/metrology.md)");
  if (o.points_file && host_seen)
    throw UsageError("inspect: give either --points FILE or HOST[:PORT] (measure live), not both");
  if (!o.points_file) o.endpoint = endpoint;  // live, localhost:1066 unless a HOST was given
  if (o.json_out && o.qif_out && *o.json_out == "-" && *o.qif_out == "-")
    throw UsageError("--json - and --qif - both want stdout; give one of them a file");
  if (o.points_file && o.feed) throw UsageError("--feed is for measuring live; --points evaluates points already measured");
  return o;
}

}  // namespace

std::string inspect_usage() {
  return "usage: messcap inspect PLAN [--points FILE | HOST[:PORT]] [--json OUT] [--html OUT]\n"
         "                      [--qif OUT] [--operator NAME] [--feed MM_S]\n"
         "Nominal-versus-actual inspection by the inspection plan PLAN (JSON: features with\n"
         "nominal geometry, probe points and scans, alignment, characteristics with tolerances;\n"
         "docs/metrology.md). Prints one line per characteristic: nominal, actual,\n"
         "deviation, tolerance, ok / OUT.\n"
         "  HOST[:PORT]      measure live (default localhost:1066): takes control, probes\n"
         "                   every feature's points with Probe cycles and runs its scans\n"
         "                   (ScanCirc, ScanLine: a measuring probe), the alignment features\n"
         "                   first, then the rest in the part frame they give; releases\n"
         "  --points FILE    evaluate points measured before: lines 'FEATURE x y z' or\n"
         "                   'FEATURE x y z i j k r' (a Hit's point, approach, tip radius;\n"
         "                   machine coordinates), or a report written by --json\n"
         "  --json OUT       the report as JSON ('-': stdout, the table then goes to stderr)\n"
         "  --html OUT       the report as one self-contained HTML page with pictures\n"
         "  --qif OUT        the results as a QIF 3.0 document (docs/qif.md; '-': stdout)\n"
         "  --operator NAME  who measured, recorded in the JSON and QIF reports\n"
         "  --feed MM_S      positioning and approach speed (default: the plan's probing.feed)\n"
         "Exit status: 0 every characteristic in tolerance; 1 a plan, points, connection,\n"
         "probing or alignment error; 2 bad arguments; 5 a characteristic out of tolerance\n"
         "or not evaluated (the reports are written all the same).\n";
}

int run_inspect_command(int argc, const char* const argv[]) {
  for (int i = 2; i < argc; ++i)
    if (std::string_view(argv[i]) == "-h" || std::string_view(argv[i]) == "--help") {
      std::cout << inspect_usage();
      return client::kExitOk;
    }
  InspectOptions o;
  try {
    o = parse_options(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << "messcap: " << e.what() << "\n(try messcap inspect --help)\n";
    return client::kExitUsage;
  }
  const bool stdout_taken = (o.json_out && *o.json_out == "-") || (o.qif_out && *o.qif_out == "-");
  std::ostream& table = stdout_taken ? std::cerr : std::cout;
  try {
    const auto plan = metrology::parse_inspection_plan(read_text_file(o.plan), o.plan);
    ReportSource source{o.plan, "", "", "", o.operator_name};
    std::vector<metrology::MeasuredPoint> points;
    if (o.points_file) {
      points = metrology::parse_measured_points(read_text_file(*o.points_file), *o.points_file);
      source.measured = "points from " + *o.points_file;
    } else {
      source.time = utc_time_now();  // when measuring starts
      source.machine = "messd at " + o.endpoint->to_string();
      source.measured = "measured on " + source.machine;
      points = measure_live(plan, LiveOptions{*o.endpoint, o.feed}, std::cerr);
    }
    if (source.time.empty()) source.time = utc_time_now();
    const auto result = metrology::evaluate_inspection(plan, points);
    print_inspection_table(table, plan, result, source);
    const std::string report = inspection_json(plan, result, source);
    if (o.json_out) write_text_file(*o.json_out, report);
    if (o.qif_out)  // from the JSON report itself: the QIF's figures are the report's
      write_text_file(*o.qif_out, qif_document({{parse_saved_inspection(report, "the report"), "the report"}},
                                               utc_time_now()));
    if (o.html_out) write_text_file(*o.html_out, inspection_html(plan, result, source));
    if (o.endpoint && !o.points_file) announce_result(plan, result, LiveOptions{*o.endpoint, o.feed}, std::cerr);
    return result.out_of_tolerance() + result.not_evaluated() > 0 ? kExitOutOfTolerance : client::kExitOk;
  } catch (const std::exception& e) {
    std::cerr << "messcap: inspect: " << e.what() << "\n";
    return client::kExitFailure;
  }
}

}  // namespace imess::messcap
