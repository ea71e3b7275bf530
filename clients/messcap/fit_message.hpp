// The one wording of a failed fit, shared by `fit`, `convert --fit` and capture `--fit`.
#pragma once
#include <cstddef>
#include <string>

#include "imess/exchange/fit_report.hpp"

namespace imess::messcap {

// "fit circle to the 2 points of pts.xyz failed (too_few_points): <library message>"
inline std::string fit_failure_message(exchange::FitKind kind, std::size_t points, const std::string& source,
                                       const metrology::FitError& error) {
  return "fit " + std::string(exchange::to_string(kind)) + " to the " + std::to_string(points) +
         (points == 1 ? " point of " : " points of ") + source + " failed (" + std::string(metrology::to_string(error.code)) +
         "): " + error.message;
}

}  // namespace imess::messcap
