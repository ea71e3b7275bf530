// Coordinate systems (IPPDME.md §7 "CartCMM"): the chain machine → MultipleArmCsy →
// MoveableMachineCsy → PartCsy, each link a SetCsyTransformation(x0, y0, z0, theta, psi, phi).
// Our reading (the NIST server's): child = R·parent + (x0, y0, z0), R the Euler rotation
// psi about z, then theta about the new x, then phi about the new z. Pure.
#pragma once
#include <array>
#include <utility>

#include "imess/ippdme/commands.hpp"

namespace imess::ippdme {

// Point3: x, y, z (scan_commands.hpp).

// One link: the rotation and offset of a SetCsyTransformation.
class CsyLink {
 public:
  CsyLink() = default;
  explicit CsyLink(const CsyTransformation& t);
  const CsyTransformation& transformation() const { return t_; }
  Point3 to_child(const Point3& parent) const;    // R·p + o
  Point3 to_parent(const Point3& child) const;    // Rᵀ·(c − o)
  Point3 vector_to_child(const Point3& v) const;  // R·v
  Point3 vector_to_parent(const Point3& v) const; // Rᵀ·v

 private:
  CsyTransformation t_{};
  double r_[3][3]{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
};

// The transformation whose link maps parent to child as q -> R·q + o (R row-major, a rotation):
// the inverse of CsyLink's construction. theta comes out in 0..180, psi and phi in [0, 360);
// where theta is 0 or 180 only psi + phi (or phi - psi) is determined, and psi is given as 0.
CsyTransformation csy_transformation(const double (&r)[3][3], const Point3& o);

// The links of the chain and the one the client works in (SetCoordSystem). The Jog and
// Sensor systems are kept and read back only: they move nothing on this machine.
class CsyChain {
 public:
  void set(CsyTarget target, const CsyTransformation& t) { link(target) = CsyLink(t); }
  const CsyTransformation& get(CsyTarget target) const { return link(target).transformation(); }
  void select(CoordSystem c) { current_ = c; }
  CoordSystem current() const { return current_; }

  // Machine coordinates <-> the current system's (points and directions).
  Point3 from_machine(const Point3& p) const;
  Point3 to_machine(const Point3& p) const;
  Point3 vector_from_machine(const Point3& v) const;
  Point3 vector_to_machine(const Point3& v) const;

 private:
  const CsyLink& link(CsyTarget target) const;
  CsyLink& link(CsyTarget target) { return const_cast<CsyLink&>(std::as_const(*this).link(target)); }
  int depth() const;  // links between machine and the current system: 0 .. 3
  CsyLink multiple_arm_, moveable_, part_, jog_display_, jog_move_, sensor_;
  CoordSystem current_ = CoordSystem::MachineCsy;
};

}  // namespace imess::ippdme
