// Part alignment (3-2-1 and plane + two holes): builds the frame of the part from fitted
// features. The returned Frame maps part coordinates to machine coordinates
// (point_to_parent(p_part) = p_machine).
#pragma once

#include <stdexcept>

#include <Eigen/Core>

#include "imess/metrology/features.hpp"
#include "imess/metrology/frame.hpp"

namespace imess::metrology {

// Alignment impossible from the given features (line perpendicular to the plane, holes that
// coincide after projection, non-finite input). Set-up code: thrown.
class AlignmentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// 3-2-1: Z = the plane normal (as given: orient it first, e.g. by probe compensation, which
// points it out of the material), X = the line direction projected into the plane (its sign as
// given), Y = Z x X. Origin: on the plane, on the projected line, and level with origin_point
// along X (the plane fixes z = 0, the line y = 0, the point x = 0).
Frame align_321(const Plane& primary, const Line3& secondary, const Eigen::Vector3d& origin_point);

// Plane + two holes: Z = plane normal, X along hole1 -> hole2 projected into the plane, origin =
// hole1 projected into the plane.
Frame align_plane_two_holes(const Plane& primary, const Eigen::Vector3d& hole1,
                            const Eigen::Vector3d& hole2);

}  // namespace imess::metrology
