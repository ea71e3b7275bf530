// messcap convert: read IN, transform into --frame, fit (--fit), write OUT whole and atomically.
// Hits (7 columns) keep their approach and tip radius into .hits and give their surface points
// to the other formats; plain points cannot become .hits.
#include "convert_command.hpp"

#include <sys/stat.h>

#include <charconv>
#include <iostream>

#include "capture_options.hpp"
#include "fit_message.hpp"
#include "frame_option.hpp"
#include "imess/client/usage_error.hpp"
#include "imess/exchange/export_format.hpp"
#include "option_value.hpp"
#include "point_input.hpp"
#include "qif_convert.hpp"

namespace imess::messcap {
namespace {

struct ConvertOptions {
  std::string input;
  OutputOptions out;
  int decimals = 6;
};

int parse_decimals(std::string_view text) {
  int value = -1;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || value < 0 || value > 12)
    throw client::UsageError("--decimals '" + std::string(text) + "': expected a whole number 0..12");
  return value;
}

ConvertOptions parse_convert_options(int argc, const char* const argv[]) {
  ConvertOptions o;
  bool force = false;
  int positional = 0;
  for (int i = 2; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a == "--force") {
      force = true;
    } else if (parse_output_option(o.out, i, argc, argv)) {
      continue;
    } else if (auto d = option_value("", "--decimals", i, argc, argv)) {
      o.decimals = parse_decimals(*d);
    } else if (a.size() > 1 && a.front() == '-') {
      throw client::UsageError("convert: unknown option '" + std::string(a) +
                               "'; accepted: --fit KIND, --frame NAME, --frames FILE, --decimals D, --force, --outer");
    } else if (positional == 0) {
      o.input = std::string(a);
      ++positional;
    } else if (positional == 1) {
      check_output_file(std::string(a));
      o.out.output = std::string(a);
      ++positional;
    } else {
      throw client::UsageError("convert: unexpected argument '" + std::string(a) + "'; usage: messcap convert IN OUT");
    }
  }
  if (positional < 2) throw client::UsageError("convert needs IN and OUT; usage: messcap convert IN OUT [options]");
  check_output_options(o.out, false, force);
  return o;
}

}  // namespace

int run_convert_command(int argc, const char* const argv[]) {
  if (converts_to_qif(argc, argv)) return run_qif_convert(argc, argv);
  ConvertOptions o;
  try {
    for (int i = 2; i < argc; ++i) {
      std::string_view a = argv[i];
      if (a == "-h" || a == "--help") {
        std::cout << capture_usage();
        return client::kExitOk;
      }
    }
    o = parse_convert_options(argc, argv);
  } catch (const client::UsageError& e) {
    std::cerr << "messcap: " << e.what() << "\n(try messcap --help)\n";
    return client::kExitUsage;
  }
  const std::string& out_path = *o.out.output;
  try {
    exchange::ExportData data;
    data.decimals = o.decimals;
    data.outer = o.out.outer;
    PointInput in = read_point_or_hit_input(o.input);
    if (exchange::export_format_for(out_path).needs_approach() && !in.probed) {
      std::cerr << "messcap: convert: " << out_path << " needs each hit's approach direction and tip radius, but "
                << input_name(o.input) << " holds plain points (x y z); a .hits file is made from hits, 7 numbers "
                << "per line (x y z i j k r), or captured with messcap -o FILE.hits (nothing written)\n";
      return client::kExitFailure;
    }
    data.points = std::move(in.points);
    if (in.probed) data.hits = std::move(in.hits);
    if (o.out.frame) {
      const auto frame = load_named_frame(*o.out.frames_file, *o.out.frame);
      for (auto& p : data.points) p = frame.point_from_parent(p);
      for (auto& h : data.hits) h = hit_from_parent(frame, h);
      data.frame = *o.out.frame;
    }
    if (o.out.fit) {
      // Like messcap fit IN: hits probe-compensated, plain points as they are.
      auto fit = in.probed ? exchange::fit_probed_points(*o.out.fit, data.hits) : exchange::fit_points(*o.out.fit, data.points);
      if (!fit) {
        std::cerr << "messcap: " << fit_failure_message(*o.out.fit, data.points.size(), input_name(o.input), fit.error())
                  << " (nothing written)\n";
        return client::kExitFailure;
      }
      data.fit = *fit;
      std::cout << exchange::to_json(*fit) << "\n";
    }
    struct stat st {};
    if (o.out.mode == OpenMode::New && ::stat(out_path.c_str(), &st) == 0) {
      std::cerr << "messcap: '" << out_path << "' exists; add --force to replace it\n";
      return client::kExitFailure;
    }
    auto slash = out_path.rfind('/');
    data.file_name = slash == std::string::npos ? out_path : out_path.substr(slash + 1);
    write_file_atomically(out_path, exchange::export_format_for(out_path).write(data));
    std::cerr << "messcap: " << data.points.size() << (data.points.size() == 1 ? " point" : " points")
              << " written to " << out_path << "\n";
  } catch (const std::exception& e) {
    std::cerr << "messcap: convert: " << e.what() << "\n";
    return client::kExitFailure;
  }
  return client::kExitOk;
}

}  // namespace imess::messcap
