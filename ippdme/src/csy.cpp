// The coordinate system chain: Euler rotations and offsets, applied link by link.
#include "imess/ippdme/csy.hpp"

#include <cmath>
#include <numbers>

namespace imess::ippdme {

CsyLink::CsyLink(const CsyTransformation& t) : t_(t) {
  const double rad = std::numbers::pi / 180;
  const double cp = std::cos(t.psi * rad), sp = std::sin(t.psi * rad);
  const double ct = std::cos(t.theta * rad), st = std::sin(t.theta * rad);
  const double cf = std::cos(t.phi * rad), sf = std::sin(t.phi * rad);
  // R = Rz(phi)·Rx(theta)·Rz(psi), each acting on coordinates: Rz(a) = [c s 0; -s c 0; 0 0 1],
  // Rx(a) = [1 0 0; 0 c s; 0 -s c].
  const double z1[3][3] = {{cp, sp, 0}, {-sp, cp, 0}, {0, 0, 1}};
  const double x[3][3] = {{1, 0, 0}, {0, ct, st}, {0, -st, ct}};
  const double z2[3][3] = {{cf, sf, 0}, {-sf, cf, 0}, {0, 0, 1}};
  double m[3][3]{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) m[i][j] += x[i][k] * z1[k][j];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      r_[i][j] = 0;
      for (int k = 0; k < 3; ++k) r_[i][j] += z2[i][k] * m[k][j];
    }
}

CsyTransformation csy_transformation(const double (&r)[3][3], const Point3& o) {
  const double deg = 180 / std::numbers::pi;
  auto mod360 = [](double a) {
    const double m = std::fmod(a, 360.0);
    return m < 0 ? m + 360.0 : (m >= 360.0 ? 0.0 : m);
  };
  CsyTransformation t{o[0], o[1], o[2], 0, 0, 0};
  // R = Rz(phi)·Rx(theta)·Rz(psi): R[2] = (st·sp, -st·cp, ct), column 2 = (sf·st, cf·st, ct).
  const double st = std::hypot(r[2][0], r[2][1]);
  t.theta = std::atan2(st, r[2][2]) * deg;
  if (st > 1e-12) {
    t.psi = mod360(std::atan2(r[2][0], -r[2][1]) * deg);
    t.phi = mod360(std::atan2(r[0][2], r[1][2]) * deg);
  } else if (r[2][2] > 0) {  // theta 0: a turn about z by psi + phi
    t.phi = mod360(std::atan2(r[0][1], r[0][0]) * deg);
  } else {                   // theta 180: Rz(phi)·diag(1, -1, -1)
    t.phi = mod360(std::atan2(-r[0][1], r[0][0]) * deg);
  }
  return t;
}

Point3 CsyLink::vector_to_child(const Point3& v) const {
  Point3 out{};
  for (int i = 0; i < 3; ++i) out[i] = r_[i][0] * v[0] + r_[i][1] * v[1] + r_[i][2] * v[2];
  return out;
}

Point3 CsyLink::vector_to_parent(const Point3& v) const {
  Point3 out{};
  for (int i = 0; i < 3; ++i) out[i] = r_[0][i] * v[0] + r_[1][i] * v[1] + r_[2][i] * v[2];
  return out;
}

Point3 CsyLink::to_child(const Point3& p) const {
  Point3 out = vector_to_child(p);
  out[0] += t_.x0;
  out[1] += t_.y0;
  out[2] += t_.z0;
  return out;
}

Point3 CsyLink::to_parent(const Point3& c) const { return vector_to_parent({c[0] - t_.x0, c[1] - t_.y0, c[2] - t_.z0}); }

const CsyLink& CsyChain::link(CsyTarget target) const {
  switch (target) {
    case CsyTarget::PartCsy: return part_;
    case CsyTarget::MoveableMachineCsy: return moveable_;
    case CsyTarget::MultipleArmCsy: return multiple_arm_;
    case CsyTarget::JogDisplayCsy: return jog_display_;
    case CsyTarget::JogMoveCsy: return jog_move_;
    case CsyTarget::SensorCsy: return sensor_;
  }
  return part_;
}

int CsyChain::depth() const {
  switch (current_) {
    case CoordSystem::MachineCsy: return 0;
    case CoordSystem::MultipleArmCsy: return 1;
    case CoordSystem::MoveableMachineCsy: return 2;
    case CoordSystem::PartCsy: return 3;
  }
  return 0;
}

Point3 CsyChain::from_machine(const Point3& p) const {
  const CsyLink* links[] = {&multiple_arm_, &moveable_, &part_};
  Point3 q = p;
  for (int i = 0; i < depth(); ++i) q = links[i]->to_child(q);
  return q;
}

Point3 CsyChain::to_machine(const Point3& p) const {
  const CsyLink* links[] = {&multiple_arm_, &moveable_, &part_};
  Point3 q = p;
  for (int i = depth() - 1; i >= 0; --i) q = links[i]->to_parent(q);
  return q;
}

Point3 CsyChain::vector_from_machine(const Point3& v) const {
  const CsyLink* links[] = {&multiple_arm_, &moveable_, &part_};
  Point3 q = v;
  for (int i = 0; i < depth(); ++i) q = links[i]->vector_to_child(q);
  return q;
}

Point3 CsyChain::vector_to_machine(const Point3& v) const {
  const CsyLink* links[] = {&multiple_arm_, &moveable_, &part_};
  Point3 q = v;
  for (int i = depth() - 1; i >= 0; --i) q = links[i]->vector_to_parent(q);
  return q;
}

}  // namespace imess::ippdme
