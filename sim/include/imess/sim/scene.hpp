// The simulated workpiece: solids built from primitives, queried by signed distance
// (positive outside material). The union of solids is the minimum of their distances.
#pragma once
#include <string>
#include <variant>
#include <vector>

#include "imess/hal/types.hpp"

namespace imess::sim {

using hal::Vec3;

// Half-space: material on the side opposite the normal (a table top, a large face).
struct PlaneSolid {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
};

// Which box edge is rounded; edges on the top face, named by the side they join.
enum class FilletEdge { None, FrontTop, BackTop, LeftTop, RightTop };

struct Bore {          // vertical through-hole, in the box's own frame
  double x = 0, y = 0; // offset from the box centre
  double diameter = 0;
};

struct BoxSolid {
  Vec3 center = Vec3::Zero();
  Vec3 size = Vec3::Ones();   // full lengths along the box's own x, y, z
  double yaw_deg = 0;         // rotation about the vertical through the centre
  FilletEdge fillet = FilletEdge::None;
  double fillet_radius = 0;
  std::vector<Bore> bores;
};

struct SphereSolid {
  Vec3 center = Vec3::Zero();
  double diameter = 0;
};

struct CylinderSolid {        // vertical shaft standing on base
  Vec3 base = Vec3::Zero();
  double diameter = 0;
  double height = 0;
};

using Solid = std::variant<PlaneSolid, BoxSolid, SphereSolid, CylinderSolid>;

class Scene {
 public:
  Scene() = default;
  explicit Scene(std::vector<Solid> solids);
  // Signed distance from p to the nearest material surface; +infinity for an empty scene.
  // Exact outside each solid and inside bores away from their rims. No allocation.
  double distance(const Vec3& p) const noexcept;
  const std::vector<Solid>& solids() const { return solids_; }

 private:
  std::vector<Solid> solids_;
};

double box_distance(const BoxSolid& box, const Vec3& p) noexcept;

// The 1996 worked example: a cube with a vertical bore and one rounded edge on a table.
Scene worked_example_scene();

// The reference sphere probes are qualified on (`messcap qualify`): a 25 mm ball, its centre
// at (750, 650, 60), on a 10 mm stem standing on the table — clear of the worked example and
// of every path the tests and examples drive (docs/configuration.md).
SphereSolid reference_sphere();
CylinderSolid reference_sphere_stem();

// The simulated table of the shipped configurations and of messd with none: the worked
// example plus the reference sphere on its stem.
Scene default_scene();

}  // namespace imess::sim
