// The plot as an SVG document: two views side by side (plot_views), each scaled to fit with
// mm (or degree) ticks on its edges, axis names and the bounding box of what it shows;
// feed moves solid, rapids dashed in orange, probing moves green with a circle at each
// target; a legend below.
#pragma once
#include <string>
#include <string_view>

#include "imess/planner/axes.hpp"
#include "path_trace.hpp"

namespace imess::messprog {

// SVG element ids and classes the drawing uses (and the tests look for):
//   <g id="view-xy">, <g id="view-xz"> (views, see plot_views), <g id="legend">;
//   <path class="feed|rapid|probe">, <circle class="probe-target">.
std::string svg_plot(const PathTrace& trace, const planner::Machine& machine, std::string_view title);

}  // namespace imess::messprog
