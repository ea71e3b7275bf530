// Synthetic probe hits for inspection tests: a true surface point and outward normal in part
// coordinates, a true placement of the part on the machine, and the hit messd would report
// (ball centre r off the surface along the normal; the point compensated along the approach).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "imess/metrology/frame.hpp"
#include "imess/metrology/inspection.hpp"

namespace imess::test {

struct SyntheticProbe {
  metrology::Frame truth;  // true part -> machine
  double tip_radius = 2.0;
  std::vector<metrology::MeasuredPoint> hits;

  // Touches the true surface point s (outward normal n) moving along `approach` (part coords).
  void touch(const std::string& feature, const Eigen::Vector3d& s, const Eigen::Vector3d& n,
             const Eigen::Vector3d& approach) {
    const Eigen::Vector3d a = approach.normalized();
    const Eigen::Vector3d centre = s + tip_radius * n.normalized();
    metrology::MeasuredPoint p;
    p.feature = feature;
    p.point = truth.point_to_parent(centre + tip_radius * a);
    p.approach = truth.direction_to_parent(a);
    p.radius = tip_radius;
    hits.push_back(p);
  }
  // Touch along the normal (the usual case).
  void touch(const std::string& feature, const Eigen::Vector3d& s, const Eigen::Vector3d& n) { touch(feature, s, n, -n); }
};

inline double deg2rad(double d) { return d * M_PI / 180.0; }

}  // namespace imess::test
