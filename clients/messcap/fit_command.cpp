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
  try {
    int positional = 0;
    for (int i = 2; i < argc; ++i) {
      std::string a = argv[i];
      if (a == "-h" || a == "--help") {
        std::cout << capture_usage();
        return client::kExitOk;
      }
      if (a.size() > 1 && a.front() == '-')
        throw client::UsageError("fit: unknown option '" + a + "'; usage: messcap fit KIND [FILE | -]");
      if (positional == 0) {
        try {
          kind = exchange::parse_fit_kind(a);
        } catch (const exchange::FitKindError& e) {
          throw client::UsageError(std::string("fit: ") + e.what());
        }
      } else if (positional == 1) {
        input = a;
      } else {
        throw client::UsageError("fit: unexpected argument '" + a + "'; usage: messcap fit KIND [FILE | -]");
      }
      ++positional;
    }
    if (!kind) throw client::UsageError("fit needs a KIND: " + std::string(exchange::kFitKinds));
  } catch (const client::UsageError& e) {
    std::cerr << "messcap: " << e.what() << "\n(try messcap --help)\n";
    return client::kExitUsage;
  }

  std::vector<Eigen::Vector3d> points;
  try {
    points = read_point_input(input);
  } catch (const std::exception& e) {
    std::cerr << "messcap: fit " << exchange::to_string(*kind) << ": " << e.what() << "\n";
    return client::kExitFailure;
  }
  auto fit = exchange::fit_points(*kind, points);
  if (!fit) {
    std::cerr << "messcap: " << fit_failure_message(*kind, points.size(), input_name(input), fit.error()) << "\n";
    return client::kExitFailure;
  }
  std::cout << exchange::to_json(*fit) << "\n";
  return client::kExitOk;
}

}  // namespace imess::messcap
