// messcap fit: read points, fit, print one JSON line; a failed fit names the points and the
// library's reason on stderr.
#include "fit_command.hpp"

#include <iostream>
#include <string>

#include "capture_options.hpp"
#include "fit_message.hpp"
#include "imess/client/usage_error.hpp"
#include "imess/exchange/fit_report.hpp"
#include "point_input.hpp"

namespace imess::messcap {

int run_fit_command(int argc, const char* const argv[]) {
  std::optional<exchange::FitKind> kind;
  std::string input = "-";
  bool surface = false;
  try {
    int positional = 0;
    for (int i = 2; i < argc; ++i) {
      std::string a = argv[i];
      if (a == "-h" || a == "--help") {
        std::cout << capture_usage();
        return client::kExitOk;
      }
      if (a == "--surface") {
        surface = true;
        continue;
      }
      if (a.size() > 1 && a.front() == '-')
        throw client::UsageError("fit: unknown option '" + a + "'; usage: messcap fit [--surface] KIND [FILE | -]");
      if (positional == 0) {
        try {
          kind = exchange::parse_fit_kind(a);
        } catch (const exchange::FitKindError& e) {
          throw client::UsageError(std::string("fit: ") + e.what());
        }
      } else if (positional == 1) {
        input = a;
      } else {
        throw client::UsageError("fit: unexpected argument '" + a + "'; usage: messcap fit [--surface] KIND [FILE | -]");
      }
      ++positional;
    }
    if (!kind) throw client::UsageError("fit needs a KIND: " + std::string(exchange::kFitKinds));
  } catch (const client::UsageError& e) {
    std::cerr << "messcap: " << e.what() << "\n(try messcap --help)\n";
    return client::kExitUsage;
  }

  PointInput in;
  try {
    in = read_point_or_hit_input(input);
  } catch (const std::exception& e) {
    std::cerr << "messcap: fit " << exchange::to_string(*kind) << ": " << e.what() << "\n";
    return client::kExitFailure;
  }
  // Hits with approach and tip radius: fit the ball centres and compensate (the default for
  // measured points); plain x y z files, or --surface, fit the surface points.
  auto fit = in.probed && !surface ? exchange::fit_probed_points(*kind, in.hits) : exchange::fit_points(*kind, in.points);
  if (!fit) {
    std::cerr << "messcap: " << fit_failure_message(*kind, in.points.size(), input_name(input), fit.error()) << "\n";
    return client::kExitFailure;
  }
  std::cout << exchange::to_json(*fit) << "\n";
  return client::kExitOk;
}

}  // namespace imess::messcap
