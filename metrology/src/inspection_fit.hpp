// One plan feature fitted to its measured points in a chosen frame: the library fit of its
// kind (probe compensated for hits), oriented like the nominal, with the compensated surface
// points and, for axes, the measured extent. Used by the alignment and the evaluation.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "imess/metrology/fit_result.hpp"
#include "imess/metrology/inspection_plan.hpp"

namespace imess::metrology::detail {

// A measured point in the frame of the fit.
struct FitInput {
  Eigen::Vector3d point;                    // surface point as measured (compensated along approach)
  std::optional<Eigen::Vector3d> approach;  // unit
  double radius = 0.0;
};

struct FittedFeature {
  Geometry geometry;
  FitStats stats;
  bool compensated = false;
  std::vector<Eigen::Vector3d> surface;     // per input point, same order
  std::optional<std::array<Eigen::Vector3d, 2>> axis_ends;
};

// `nominal` in the same frame as the inputs (its kind, start values and orientation are used).
Fit<FittedFeature> fit_feature(const std::string& name, const Geometry& nominal, const std::vector<FitInput>& inputs);

}  // namespace imess::metrology::detail
