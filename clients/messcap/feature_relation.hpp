// Distance and angle between two fitted features (`messcap relate`): what each feature is for
// a distance (a centre, an axis or a plane) and for an angle (an axis or a plane normal), and
// the rules of docs/metrology.md §12.1. A is the reference; `from` lies on A, `to` on B.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "imess/exchange/fit_report.hpp"

namespace imess::messcap {

// Two planes, two axes or an axis and a plane count as parallel within this angle (degrees):
// then their distance is defined (a point of B to A) and no skew or intersection is sought.
inline constexpr double kParallelDeg = 1.0;

struct Relation {
  exchange::FitKind a = exchange::FitKind::Plane, b = exchange::FitKind::Plane;
  std::optional<double> distance;        // mm, >= 0
  std::string distance_rule;             // "point-plane", "axis-axis" (skew), "axis-axis parallel", …
  std::optional<Eigen::Vector3d> from;   // on A: where the distance is measured from
  std::optional<Eigen::Vector3d> to;     // on B
  std::optional<double> angle_deg;       // 0 … 90
  std::string angle_rule;                // "axis-axis", "axis-plane", "plane-plane"
  std::vector<std::string> notes;        // why a distance or an angle is missing
};

Relation relate(const exchange::FitReport& a, const exchange::FitReport& b);

// One JSON object on one line: a, b, distance, distance_rule, from, to, angle_deg, angle_rule,
// notes (each only when it has a value).
std::string to_json(const Relation& relation);

}  // namespace imess::messcap
