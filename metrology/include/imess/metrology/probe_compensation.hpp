// Probe (tip radius) compensation: features are fitted to the probe ball centres, then offset
// by the tip radius along the fitted normal, on the side the approach directions show.
#pragma once

#include <span>

#include <Eigen/Core>

#include "imess/metrology/features.hpp"
#include "imess/metrology/fit_result.hpp"

namespace imess::metrology {

// Where the material is relative to the fitted centre or axis.
enum class MaterialSide : int {
  Inner = 1,  // bore, hole, hollow sphere, inner cone: material outside, probe moved outward
  Outer = 2,  // shaft, ball, boss, outer cone: material inside, probe moved inward
};

// Hits whose approach is closer than this cosine to tangential do not vote on the side
// (about 3 degrees off the surface); they are still compensated along the fitted normal.
inline constexpr double kMinApproachCosine = 0.05;

// Inputs per hit i: the ball centre centres[i] and the approach (motion) direction approach[i]
// at the moment of contact (any length > 0). tip_radius >= 0. All decisive hits must agree on
// the side, otherwise FitErrorCode::InconsistentApproach names the first hit that disagrees.
//
// Plane: the material is where the probe moved to; the plane moves by r that way and its normal
//        is re-oriented to point out of the material (toward the probe).
// Circle / sphere / cylinder: approach pointing away from the centre/axis = Inner (radius + r),
//        toward it = Outer (radius - r).
// Cone: same rule with the cone's surface normal; the apex angle is kept and the orthogonal
//        distance from the axis point changes by +r (Inner) or -r (Outer).
// Residual statistics are those of the centre fit (the offset surface has the same residuals;
// the plane's are negated when its normal is flipped).
Fit<Plane> compensate(const Plane& centre_fit, std::span<const Eigen::Vector3d> centres,
                      std::span<const Eigen::Vector3d> approach, double tip_radius);
Fit<Circle2> compensate(const Circle2& centre_fit, std::span<const Eigen::Vector2d> centres,
                        std::span<const Eigen::Vector2d> approach, double tip_radius);
Fit<Circle3> compensate(const Circle3& centre_fit, std::span<const Eigen::Vector3d> centres,
                        std::span<const Eigen::Vector3d> approach, double tip_radius);
Fit<Sphere> compensate(const Sphere& centre_fit, std::span<const Eigen::Vector3d> centres,
                       std::span<const Eigen::Vector3d> approach, double tip_radius);
Fit<Cylinder> compensate(const Cylinder& centre_fit, std::span<const Eigen::Vector3d> centres,
                         std::span<const Eigen::Vector3d> approach, double tip_radius);
Fit<Cone> compensate(const Cone& centre_fit, std::span<const Eigen::Vector3d> centres,
                     std::span<const Eigen::Vector3d> approach, double tip_radius);

// The side the approach directions show for a round feature (same voting as compensate()).
Fit<MaterialSide> material_side(const Circle3& fit, std::span<const Eigen::Vector3d> centres,
                                std::span<const Eigen::Vector3d> approach);
Fit<MaterialSide> material_side(const Sphere& fit, std::span<const Eigen::Vector3d> centres,
                                std::span<const Eigen::Vector3d> approach);
Fit<MaterialSide> material_side(const Cylinder& fit, std::span<const Eigen::Vector3d> centres,
                                std::span<const Eigen::Vector3d> approach);
Fit<MaterialSide> material_side(const Cone& fit, std::span<const Eigen::Vector3d> centres,
                                std::span<const Eigen::Vector3d> approach);

// Fit to the centres, then compensate: the usual entry points for probed features.
Fit<Plane> fit_plane_probed(std::span<const Eigen::Vector3d> centres,
                            std::span<const Eigen::Vector3d> approach, double tip_radius);
Fit<Circle2> fit_circle2d_probed(std::span<const Eigen::Vector2d> centres,
                                 std::span<const Eigen::Vector2d> approach, double tip_radius,
                                 const FitOptions& options = {});
Fit<Circle3> fit_circle3d_probed(std::span<const Eigen::Vector3d> centres,
                                 std::span<const Eigen::Vector3d> approach, double tip_radius,
                                 const FitOptions& options = {});
Fit<Sphere> fit_sphere_probed(std::span<const Eigen::Vector3d> centres,
                              std::span<const Eigen::Vector3d> approach, double tip_radius,
                              const FitOptions& options = {});
Fit<Cylinder> fit_cylinder_probed(std::span<const Eigen::Vector3d> centres,
                                  std::span<const Eigen::Vector3d> approach, double tip_radius,
                                  const FitOptions& options = {});
Fit<Cone> fit_cone_probed(std::span<const Eigen::Vector3d> centres,
                          std::span<const Eigen::Vector3d> approach, double tip_radius,
                          const FitOptions& options = {});

}  // namespace imess::metrology
