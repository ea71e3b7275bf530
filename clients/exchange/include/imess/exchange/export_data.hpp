// ExportData: what every point-file writer gets — the points (with their approach and tip
// radius when the source had them), an optional fitted feature, the number of decimals to
// print and a few words of provenance.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "imess/exchange/fit_report.hpp"
#include "imess/metrology/point_file.hpp"

namespace imess::exchange {

struct ExportData {
  std::vector<Eigen::Vector3d> points;  // mm
  // The hits behind `points` (same order, hits[i].surface == points[i]) when the source knew
  // each one's approach and tip radius; empty otherwise. Only .hits needs them.
  std::vector<metrology::ProbedPoint> hits;
  std::optional<FitReport> fit;         // written by the formats that can hold one (.json, .dmi)
  int decimals = 3;                     // coordinates printed with this many decimals
  std::string frame;                    // the frame the coordinates are in; empty = machine
  std::string source = "IMESS messcap";  // who wrote it (headers that have a place for it)
  std::string file_name = "points";      // the file's own name, for headers that record it
  bool outer = false;  // DMIS: the fitted circle/sphere/cylinder/cone is OUTER (a shaft), not INNER
};

// `value` with `decimals` decimals ("%.*f"), never "-0.000".
std::string fixed(double value, int decimals);

}  // namespace imess::exchange
