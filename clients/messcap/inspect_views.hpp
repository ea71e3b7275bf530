// The HTML report's three orthographic views: the nominal part drawn from the plan (the
// outline its opposite planes make, each plane's extent over the part and its probe points,
// circles, cylinders, spheres, lines, points), the measured points coloured by their deviation,
// scale ticks in mm, and labels that neither overlap nor leave the picture.
#pragma once

#include <string>

#include "imess/metrology/inspection.hpp"
#include "imess/metrology/inspection_plan.hpp"

namespace imess::messcap {

struct ViewAxes {
  const char* title;        // "top (X–Y)"
  int u, v;                 // the part axes across (to the right) and up
  const char* u_name;
  const char* v_name;
};

// One view as an SVG <figure>; `scale`: the deviation (mm) shown fully red or blue.
std::string inspection_view(const metrology::InspectionPlan& plan, const metrology::InspectionResult& result,
                            const ViewAxes& view, double scale);
// Blue (-1) through green (0) to red (+1), as "#rrggbb".
std::string deviation_colour(double t);
// Text for HTML and SVG: & < > " as entities.
std::string html_escaped(const std::string& s);

}  // namespace imess::messcap
