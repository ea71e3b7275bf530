// Touches whose approach is NOT along the surface normal, as a probe meets a sphere or a plane
// when it is driven slantwise: the ball centre at contact, the approach direction, and the
// surface point messd reports for it (ball centre + r·approach, which is off the surface).
// Fitting those reported points plainly gives a wrong feature; the ball centres give the
// true one — the difference probe compensation with the approach makes.
#pragma once
#include <cmath>
#include <vector>

#include <Eigen/Core>

namespace imess::test {

struct TiltedTouch {
  Eigen::Vector3d centre;    // the ball centre when it touches
  Eigen::Vector3d approach;  // unit motion direction
  double tip = 0;            // ball radius
  Eigen::Vector3d reported() const { return centre + tip * approach; }
};

inline double degrees(double deg) { return deg * M_PI / 180.0; }

// Touches on the upper part of a sphere: at each elevation (deg above its equator) and azimuth
// (deg), approaching against the outward normal tilted by `tilt` (deg) sideways (horizontally).
inline std::vector<TiltedTouch> sphere_touches(const Eigen::Vector3d& centre, double radius, double tip, double tilt,
                                               const std::vector<std::pair<double, double>>& elevation_azimuth) {
  std::vector<TiltedTouch> out;
  for (auto [el, az] : elevation_azimuth) {
    const Eigen::Vector3d n(std::cos(degrees(el)) * std::cos(degrees(az)), std::cos(degrees(el)) * std::sin(degrees(az)),
                            std::sin(degrees(el)));
    const Eigen::Vector3d side(-std::sin(degrees(az)), std::cos(degrees(az)), 0);
    out.push_back({centre + (radius + tip) * n, -std::cos(degrees(tilt)) * n + std::sin(degrees(tilt)) * side, tip});
  }
  return out;
}

// Touches on a horizontal top face at height z: at each (x, y), coming down tilted by `tilt`
// (deg) from the vertical toward the azimuth (deg) given with the point.
inline std::vector<TiltedTouch> top_face_touches(double z, double tip, double tilt,
                                                 const std::vector<Eigen::Vector3d>& x_y_azimuth) {
  std::vector<TiltedTouch> out;
  for (const auto& p : x_y_azimuth) {
    const Eigen::Vector3d d(std::sin(degrees(tilt)) * std::cos(degrees(p.z())),
                            std::sin(degrees(tilt)) * std::sin(degrees(p.z())), -std::cos(degrees(tilt)));
    out.push_back({Eigen::Vector3d(p.x(), p.y(), z + tip), d, tip});
  }
  return out;
}

}  // namespace imess::test
