// Where things go on the plot: which machine axes each view draws (X-Y on top, X-Z in front;
// without Z the machine's third axis), the scale that fits the path into a square panel with
// equal units in both directions, and round tick values for its edges.
#pragma once
#include <string>
#include <vector>

#include "imess/planner/axes.hpp"
#include "path_trace.hpp"

namespace imess::messprog {

struct ViewAxes {
  int h = 0, v = -1;  // machine axis indices: horizontal, vertical (-1: the machine has none)
  std::string id;     // "view-xy", "view-xz", "view-xc"
  std::string title;  // "X-Y (top)", "X-Z (front)", "X-C (C against X)"
};

// The two views of a machine with two or more axes.
std::vector<ViewAxes> plot_views(const planner::Machine& machine);

struct Range {
  double lo = 0, hi = 0;
  bool empty = true;
  void add(double x);
};

// A view's panel: `size` pixels square, its left top corner at (left, top).
struct Panel {
  double left = 0, top = 0, size = 400;
};

// Data (h, v) to pixels: the data box (padded 5 %) fits the panel, centred, one scale for both
// directions; a path with no extent gets a 10-unit square around it.
class ViewScale {
 public:
  ViewScale(const Range& h, const Range& v, const Panel& panel);
  double x(double h) const { return panel_.left + panel_.size / 2 + (h - hc_) * scale_; }
  double y(double v) const { return panel_.top + panel_.size / 2 - (v - vc_) * scale_; }
  // The data values at the panel's edges.
  double h_lo() const { return hc_ - panel_.size / 2 / scale_; }
  double h_hi() const { return hc_ + panel_.size / 2 / scale_; }
  double v_lo() const { return vc_ - panel_.size / 2 / scale_; }
  double v_hi() const { return vc_ + panel_.size / 2 / scale_; }

 private:
  Panel panel_;
  double hc_ = 0, vc_ = 0, scale_ = 1;
};

// Round values (steps of 1, 2 or 5 × 10^k, five to ten of them) within [lo, hi].
std::vector<double> ticks(double lo, double hi);
// Decimals that print every tick of that spacing exactly (step 0.5 → 1, step 20 → 0).
int tick_decimals(const std::vector<double>& ticks);

}  // namespace imess::messprog
