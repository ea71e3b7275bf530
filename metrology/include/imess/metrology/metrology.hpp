// Umbrella header of imess::metrology: fits, probe compensation, comparison metrics, frames,
// alignment, the 5-axis offset convention, the point file reader and inspection plans.
#pragma once

#include "imess/metrology/alignment.hpp"
#include "imess/metrology/compare.hpp"
#include "imess/metrology/features.hpp"
#include "imess/metrology/fit.hpp"
#include "imess/metrology/fit_result.hpp"
#include "imess/metrology/five_axis.hpp"
#include "imess/metrology/frame.hpp"
#include "imess/metrology/frame_store.hpp"
#include "imess/metrology/inspection.hpp"
#include "imess/metrology/inspection_plan.hpp"
#include "imess/metrology/inspection_points.hpp"
#include "imess/metrology/point_file.hpp"
#include "imess/metrology/probe_compensation.hpp"
