// Probe qualification on a reference sphere (docs/metrology.md "Probe qualification"): where
// the ball is to touch the sphere (a ring a little above the equator plus the pole), and what
// the touches say — the effective tip radius, the probe offset and the sphere's form.
#pragma once

#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "imess/metrology/features.hpp"
#include "imess/metrology/point_file.hpp"

namespace imess::messcap {

// The touches do not give a qualification: too few, no approach, no sphere fits, a radius <= 0.
class QualificationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ReferenceSphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // nominal, machine coordinates
  double diameter = 0;                                // calibrated
  double radius() const { return diameter / 2; }
};

// How the sphere is touched. The ring's points are spread evenly from the +X direction on.
struct TouchPattern {
  int ring_points = 8;
  double ring_elevation_deg = 10;  // above the equator: the stylus shaft stays clear of the ball
  double clearance = 5;            // mm: the start of each touch off the surface, along the normal
  double safe_height = 20;         // mm above the top of the ball (plus tip) to move between touches
};

// One touch: ball-centre positions (machine coordinates).
struct Touch {
  Eigen::Vector3d start;     // clearance off the sphere, on the normal through the target
  Eigen::Vector3d target;    // the ball centre when the ball touches the nominal sphere
  Eigen::Vector3d approach;  // unit, toward the sphere's centre
};

struct TouchPlan {
  std::vector<Touch> touches;  // the ring, then the pole
  double safe_z = 0;           // height of every move between touches
};

// `tip_radius`: the radius the touches are planned with (the one in use; only where the ball
// starts and aims depends on it, not the result). Throws QualificationError for a pattern
// outside its range (ring_points 3 … 72, elevation 0 … 60 degrees, clearance > 0).
TouchPlan plan_touches(const ReferenceSphere& sphere, double tip_radius, const TouchPattern& pattern = {});

struct Qualification {
  metrology::Sphere centre_fit;       // the sphere of the ball centres
  double tip_radius = 0;              // effective: centre_fit radius - sphere radius
  Eigen::Vector3d shift;              // nominal centre - fitted centre
  Eigen::Vector3d offset;             // the new probe offset: previous + shift
  double form = 0;                    // range of the centres' radial residuals
  std::vector<Eigen::Vector3d> centres;
  std::vector<double> residuals;      // signed, distance from the fitted centre - fitted radius
};

// Fits the ball centres of the hits (surface point - radius * approach, as messd reports them)
// with a sphere. `previous_offset`: the probe offset the hits were reported with. Throws
// QualificationError (fewer than 4 hits, a hit without approach, the fit's own error, a
// fitted sphere not larger than the reference sphere).
Qualification qualify_probe(const ReferenceSphere& sphere, std::span<const metrology::ProbedPoint> hits,
                            const Eigen::Vector3d& previous_offset);

struct QualificationLimits {
  double max_form = 0.005;   // mm
  double max_tip_radius = 50;  // messd's TipRadius range
  double max_offset = 100;     // messd's ProbeOff range, per axis
};

// Why the qualification must not be used, or nothing: a form error above the limit (a dirty
// sphere or stylus, a loose stylus, a touch off the sphere), a radius or offset messd cannot hold.
std::optional<std::string> refusal(const Qualification& q, const QualificationLimits& limits);

}  // namespace imess::messcap
