// A fitted feature as messcap reports it: the kinds `messcap fit` accepts, the library fit
// behind each, and the flat result (the fields of its JSON object) the writers share.
#pragma once
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "imess/metrology/fit_result.hpp"
#include "imess/metrology/point_file.hpp"

namespace imess::exchange {

enum class FitKind { Line, Line2d, Plane, Circle, Circle2d, Sphere, Cylinder, Cone };

// A KIND word that is not one of kFitKinds; the message lists the accepted words.
struct FitKindError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

inline constexpr std::string_view kFitKinds = "line, line2d, plane, circle, circle2d, sphere, cylinder, cone";

FitKind parse_fit_kind(std::string_view word);  // throws FitKindError
std::string_view to_string(FitKind kind);       // "circle2d"

// Everything a writer may print. Unused fields stay empty; vectors are unit where they are
// directions. 2-D kinds are embedded back into space (see fit_points).
struct FitReport {
  FitKind kind = FitKind::Plane;
  std::optional<Eigen::Vector3d> point;      // line / plane: centroid; cylinder / cone: on the axis
  std::optional<Eigen::Vector3d> direction;  // line
  std::optional<Eigen::Vector3d> normal;     // plane, circle; line2d: of its coordinate plane
  std::optional<Eigen::Vector3d> center;     // circle, sphere
  std::optional<Eigen::Vector3d> axis;       // cylinder; cone: toward increasing radius
  std::optional<double> diameter;            // circle, sphere, cylinder; cone: through `point`
  std::optional<Eigen::Vector3d> apex;       // cone
  std::optional<double> apex_angle_deg;      // cone: full angle
  double rms = 0.0;
  double form_min = 0.0;  // most negative residual (library sign convention)
  double form_max = 0.0;  // most positive residual
  std::size_t n = 0;
};

// Fits with imess::metrology (never a second implementation). line2d and circle2d need the
// points in a coordinate plane (one coordinate the same for all, within 1e-9 of their extent;
// z is preferred, then y, then x): the other two are fitted and the result embedded again.
// A failure carries the library's FitError (or InvalidArgument for the coordinate-plane rule).
metrology::Fit<FitReport> fit_points(FitKind kind, std::span<const Eigen::Vector3d> points);

// Probe-compensated fit (docs/metrology.md 3): the library's fit_*_probed on the ball centres
// (surface - r * approach) with the approach directions and the tip radius, for plane, circle,
// sphere, cylinder and cone (has_probed_fit). The other kinds (line, line2d, circle2d) are fitted
// to the surface points. Every hit needs an approach direction, and all one tip radius.
bool has_probed_fit(FitKind kind);
metrology::Fit<FitReport> fit_probed_points(FitKind kind, std::span<const metrology::ProbedPoint> hits);

// One JSON object on one line, keys in the documented order (type, point, direction, normal,
// center, axis, diameter, apex, apex_angle_deg, rms, form_min, form_max, n), full precision.
std::string to_json(const FitReport& report);

}  // namespace imess::exchange
