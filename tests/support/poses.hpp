// X Y Z as a planner pose and back: the first three axes of a machine whose axes start X Y Z.
#pragma once
#include "imess/hal/types.hpp"
#include "imess/planner/axes.hpp"

namespace imess::test {

inline planner::Pose pose3(const hal::Vec3& v) {
  planner::Pose p{};
  for (int a = 0; a < 3; ++a) p[a] = v[a];
  return p;
}
inline hal::Vec3 vec3(const planner::Pose& p) { return {p[0], p[1], p[2]}; }

}  // namespace imess::test
