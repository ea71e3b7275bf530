// Starting cones: a short descent from every direction of the search grid, the best distinct
// ends kept (docs/metrology.md 2.5).
#include "cone_start.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "axis_start.hpp"

namespace imess::metrology::detail {
namespace {

using State = ConeProblem::State;

// Start for a given axis line: the radius as a straight-line function of the axial position.
State start_on_axis(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& c, const Eigen::Vector3d& a) {
  const Eigen::Index n = q.cols();
  Eigen::MatrixXd m(n, 2);
  Eigen::VectorXd rho(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d d = q.col(i) - c;
    m(i, 0) = 1.0;
    m(i, 1) = a.dot(d);
    rho(i) = a.cross(d).norm();
  }
  const Eigen::Vector2d k = m.colPivHouseholderQr().solve(rho);
  State st;
  st.c = c - c.dot(a) * a;
  st.a = a;
  st.phi = std::atan(k(1));
  st.s = (k(0) + k(1) * (st.c - c).dot(a)) * std::cos(st.phi);
  return st;
}

// The cone about a fixed direction: closed form plus the short direction-held iteration of
// cone_on_direction, or, when that is degenerate, the projected circle and a straight radius line.
std::optional<State> start_on_direction(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& axis) {
  if (auto f = cone_on_direction(q, axis)) {
    State st;
    st.c = f->point;
    st.a = axis;
    st.phi = std::atan(f->slope);
    st.s = f->radius * std::cos(st.phi);
    return st;
  }
  if (auto pos = axis_position(q, axis)) return start_on_axis(q, pos->point, axis);
  return std::nullopt;
}

// At most `steps` damped Gauss–Newton steps on all six parameters from st (normal equations with
// the columns scaled to unit diagonal, Marquardt damping on a rejected step). Returns the sum of
// squares at the end. A screen, not a solver: the ends are only compared with each other.
double descend(const ConeProblem& pb, State& st, int steps) {
  Eigen::Matrix<double, 6, 6> jtj;
  ConeProblem::Row jtr;
  double ssq = pb.normal_equations(st, jtj, jtr);
  Eigen::Matrix<double, 6, 6> jtj_trial;
  ConeProblem::Row jtr_trial;
  // Settled: the points lie on the cone to 1e-12 of the data size, a step lowered the sum of
  // squares by no more than 1e-12 of it, or the damping has grown so large that no step lowers it.
  const double exact_ssq = std::pow(kConeScreenExact * pb.length(), 2) * static_cast<double>(pb.residual_count());
  double mu = 0.0;
  bool settled = false;
  for (int k = 0; k < steps && !settled && ssq > exact_ssq && mu < kConeScreenStall; ++k) {
    const ConeProblem::Row d = jtj.diagonal().cwiseSqrt();
    if (!(d.minCoeff() > 0.0)) break;
    Eigen::Matrix<double, 6, 6> a = d.cwiseInverse().asDiagonal() * jtj * d.cwiseInverse().asDiagonal();
    a.diagonal().array() += mu;
    const Eigen::LLT<Eigen::Matrix<double, 6, 6>> llt(a);
    if (llt.info() != Eigen::Success) {
      mu = mu == 0.0 ? 1e-3 : 10.0 * mu;
      continue;
    }
    const ConeProblem::Row delta = llt.solve(-jtr.cwiseQuotient(d)).cwiseQuotient(d);
    const State trial = pb.apply(st, delta);
    const double ssq_trial = pb.normal_equations(trial, jtj_trial, jtr_trial);
    if (std::isfinite(ssq_trial) && ssq_trial < ssq) {
      settled = ssq - ssq_trial <= kConeScreenSettled * ssq;
      st = trial;
      ssq = ssq_trial;
      jtj = jtj_trial;
      jtr = jtr_trial;
      mu = mu < 1e-6 ? 0.0 : 0.1 * mu;
    } else {
      mu = mu == 0.0 ? 1e-3 : 10.0 * mu;
    }
  }
  return ssq;
}

// A descent's end that is a cone: finite, half apex angle below 90 degrees.
bool usable(double ssq, const State& st) {
  return std::isfinite(ssq) && st.c.allFinite() && st.a.allFinite() && std::isfinite(st.s) &&
         std::abs(st.phi) < 0.5 * std::numbers::pi;
}

}  // namespace

std::vector<State> cone_starts(const Eigen::Matrix3Xd& qs, const PrincipalAxes<3>& pa) {
  static const std::vector<Eigen::Vector3d> grid = hemisphere_directions(kDirectionGrid);
  const ConeProblem pb(qs, rms_spread<3>(qs));
  std::vector<Eigen::Vector3d> dirs = candidate_axes(qs, pa);
  dirs.insert(dirs.end(), grid.begin(), grid.end());
  // Screen: a few steps from every direction.
  std::vector<std::pair<double, State>> ends;
  for (const Eigen::Vector3d& axis : dirs) {
    auto st = start_on_direction(qs, axis);
    if (!st) continue;
    const double ssq = descend(pb, *st, kConeScreenSteps);
    if (usable(ssq, *st)) ends.emplace_back(ssq, *st);
  }
  const auto by_ssq = [](const auto& x, const auto& y) { return x.first < y.first; };
  std::stable_sort(ends.begin(), ends.end(), by_ssq);
  // Race: the best ones go on until they settle, so that ends of one basin coincide.
  if (ends.size() > kConeRaceKeep) ends.resize(kConeRaceKeep);
  for (auto& [ssq, st] : ends) {
    State longer = st;
    const double ssq_longer = descend(pb, longer, kConeRaceSteps);
    if (usable(ssq_longer, longer)) {
      st = longer;
      ssq = ssq_longer;
    }
  }
  std::stable_sort(ends.begin(), ends.end(), by_ssq);
  std::vector<State> starts;
  for (const auto& end : ends) {
    const State& st = end.second;  // a named reference, not a structured binding: clang 14 cannot capture those
    const bool seen = std::any_of(starts.begin(), starts.end(),
                                  [&](const State& k) { return pb.same_solution(k, st, kConeScreenSame); });
    if (!seen) starts.push_back(st);
    if (starts.size() == kConeScreenKeep) break;
  }
  return starts;
}

}  // namespace imess::metrology::detail
