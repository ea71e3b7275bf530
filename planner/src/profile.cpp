// The trapezoid and the evaluation of a piecewise polynomial profile.
#include "imess/planner/profile.hpp"

#include <algorithm>
#include <cmath>

namespace imess::planner {

PathState Profile::at(double t) const noexcept {
  if (count == 0) return {length, 0, 0};
  if (t >= duration) {
    const ProfilePiece& p = pieces[count - 1];
    const double d = p.duration;
    return {length, p.v0 + p.a0 * d + 0.5 * p.j * d * d, 0};
  }
  if (t < 0) t = 0;
  int i = 0;
  while (i + 1 < count && t >= pieces[i + 1].t0) ++i;
  const ProfilePiece& p = pieces[i];
  const double u = t - p.t0;
  double s = p.s0 + u * (p.v0 + u * (0.5 * p.a0 + u * p.j / 6));
  s = std::clamp(s, 0.0, length);
  return {s, p.v0 + u * (p.a0 + 0.5 * p.j * u), p.a0 + p.j * u};
}

Trapezoid plan_trapezoid(double length, double v0, double vc_max, double v1, double a) noexcept {
  Trapezoid t;
  t.a = a;
  if (length <= 0 || a <= 0) return t;  // nothing to travel: v0 = v1 = 0
  // Absorb rounding in the look-ahead: the reachable ends.
  v1 = std::min(v1, std::sqrt(v0 * v0 + 2 * a * length));
  v0 = std::min(v0, std::sqrt(v1 * v1 + 2 * a * length));
  double vc = std::max({vc_max, v0, v1});
  const double peak2 = a * length + 0.5 * (v0 * v0 + v1 * v1);  // triangle
  if (vc * vc > peak2) vc = std::max({std::sqrt(peak2), v0, v1});
  const double d_acc = (vc * vc - v0 * v0) / (2 * a), d_dec = (vc * vc - v1 * v1) / (2 * a);
  const double d_cruise = std::max(0.0, length - d_acc - d_dec);
  t.v0 = v0, t.vc = vc, t.v1 = v1;
  t.t_acc = (vc - v0) / a;
  t.t_dec = (vc - v1) / a;
  t.t_cruise = vc > 0 ? d_cruise / vc : 0;
  return t;
}

Profile trapezoid_profile(double length, const Trapezoid& t) noexcept {
  Profile p;
  p.length = length;
  if (length <= 0) return p;
  double at = 0, s = 0;
  auto piece = [&](double duration, double v0, double a0) {
    if (duration <= 0) return;
    p.pieces[p.count++] = ProfilePiece{at, duration, s, v0, a0, 0};
    at += duration;
    s += v0 * duration + 0.5 * a0 * duration * duration;
  };
  piece(t.t_acc, t.v0, t.a);
  piece(t.t_cruise, t.vc, 0);
  // The last piece starts where it must to end exactly on L.
  if (t.t_dec > 0) {
    s = length - (t.vc + t.v1) * 0.5 * t.t_dec;
    piece(t.t_dec, t.vc, -t.a);
  }
  p.duration = at;
  return p;
}

Profile rest_profile(double duration) noexcept {
  Profile p;
  if (duration > 0) {
    p.pieces[0] = ProfilePiece{0, duration, 0, 0, 0, 0};
    p.count = 1;
    p.duration = duration;
  }
  return p;
}

}  // namespace imess::planner
