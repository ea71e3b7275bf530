// The 3-2-1 frame of three plan features (primary plane, secondary plane or line, tertiary
// point, plane, circle or sphere), the same construction for nominals and measured fits.
#pragma once

#include "imess/metrology/frame.hpp"
#include "imess/metrology/inspection_plan.hpp"

namespace imess::metrology::detail {

// Throws AlignmentError when the features give no frame (secondary perpendicular to the primary,
// tertiary plane parallel to the X axis).
Frame frame_321(const Geometry& primary, const Geometry& secondary, const Geometry& tertiary);

}  // namespace imess::metrology::detail
