// Orthogonal-distance (Gaussian, L2) least-squares fits of the basic geometric elements.
// Every fit returns Fit<Feature>: the element or a FitError saying which input is bad and why.
#pragma once

#include <span>

#include <Eigen/Core>

#include "imess/metrology/features.hpp"
#include "imess/metrology/fit_result.hpp"

namespace imess::metrology {

// Minimum point counts (exactly determined cases interpolate the points).
inline constexpr std::size_t kMinPointsLine = 2;
inline constexpr std::size_t kMinPointsPlane = 3;
inline constexpr std::size_t kMinPointsCircle = 3;
inline constexpr std::size_t kMinPointsSphere = 4;
inline constexpr std::size_t kMinPointsCylinder = 5;
inline constexpr std::size_t kMinPointsCone = 6;

// Closed form: centroid + principal direction of the centred data (SVD).
Fit<Line2> fit_line2d(std::span<const Eigen::Vector2d> points);
Fit<Line3> fit_line3d(std::span<const Eigen::Vector3d> points);
// Closed form: centroid + direction of least spread (SVD).
Fit<Plane> fit_plane(std::span<const Eigen::Vector3d> points);

// Iterative: algebraic start, then Levenberg–Marquardt with analytic Jacobian.
Fit<Circle2> fit_circle2d(std::span<const Eigen::Vector2d> points, const FitOptions& options = {});
// Plane fit, projection into the plane, then fit_circle2d in plane coordinates.
Fit<Circle3> fit_circle3d(std::span<const Eigen::Vector3d> points, const FitOptions& options = {});
Fit<Sphere> fit_sphere(std::span<const Eigen::Vector3d> points, const FitOptions& options = {});
// Several starting axes (principal axes of the data, axis of an algebraic quadric fit) are
// each refined; the one with the smallest sum of squares wins.
Fit<Cylinder> fit_cylinder(std::span<const Eigen::Vector3d> points, const FitOptions& options = {});
Fit<Cone> fit_cone(std::span<const Eigen::Vector3d> points, const FitOptions& options = {});

// Refinement from a caller's starting value (e.g. the nominal from CAD, or a previous fit) when
// the data are too partial for the automatic start. Only the geometry of `start` is used.
Fit<Cylinder> fit_cylinder(std::span<const Eigen::Vector3d> points, const Cylinder& start,
                           const FitOptions& options = {});
Fit<Cone> fit_cone(std::span<const Eigen::Vector3d> points, const Cone& start,
                   const FitOptions& options = {});

}  // namespace imess::metrology
