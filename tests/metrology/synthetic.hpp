// Test helper: synthetic data sets with a known least-squares solution. Points lie on an exact
// primitive and are moved along the surface normal by deviations made orthogonal to the columns
// of the Jacobian at the true parameters, so the exact primitive is the least-squares fit.
// The Jacobian here is built independently of the library: a rigid motion (t, w) of a surface
// changes the signed distance of p by -n.(t + w x (p - c)), plus the size parameters' columns.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "imess/metrology/features.hpp"

namespace imess::metrology::test {

inline constexpr double kPi = std::numbers::pi;
inline double deg(double d) { return d * kPi / 180.0; }

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen_); }
  double normal(double sigma) { return std::normal_distribution<double>(0.0, sigma)(gen_); }
  Eigen::Vector3d unit_vector() {
    Eigen::Vector3d v;
    do {
      v = Eigen::Vector3d(normal(1.0), normal(1.0), normal(1.0));
    } while (v.norm() < 1e-3);
    return v.normalized();
  }

 private:
  std::mt19937_64 gen_;
};

// Two unit vectors completing a (unit) to an orthonormal basis; independent of the library's.
inline void basis_of(const Eigen::Vector3d& a, Eigen::Vector3d& u, Eigen::Vector3d& v) {
  const Eigen::Vector3d helper = std::abs(a.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  u = a.cross(helper).normalized();
  v = a.cross(u);
}

// e minus its projection onto the column space of J, so that J^T e = 0 afterwards.
inline Eigen::VectorXd orthogonal_to(const Eigen::MatrixXd& J, const Eigen::VectorXd& e) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinU);
  const Eigen::VectorXd sv = svd.singularValues();
  Eigen::Index rank = 0;
  while (rank < sv.size() && sv(rank) > 1e-11 * sv(0)) ++rank;
  const Eigen::MatrixXd u = svd.matrixU().leftCols(rank);
  return e - u * (u.transpose() * e);
}

// Alternating-sign deviations of random size in [amplitude/2, amplitude].
inline Eigen::VectorXd alternating(Rng& rng, std::size_t n, double amplitude) {
  Eigen::VectorXd e(static_cast<Eigen::Index>(n));
  for (Eigen::Index i = 0; i < e.size(); ++i)
    e(i) = (i % 2 == 0 ? 1.0 : -1.0) * rng.uniform(0.5 * amplitude, amplitude);
  return e;
}

// Row i of a Jacobian with respect to a rigid motion about c: [-n, -(p - c) x n].
inline void rigid_row(Eigen::MatrixXd& J, Eigen::Index i, const Eigen::Vector3d& p,
                      const Eigen::Vector3d& c, const Eigen::Vector3d& n) {
  J.block<1, 3>(i, 0) = -n.transpose();
  J.block<1, 3>(i, 3) = -((p - c).cross(n)).transpose();
}

// Largest cosine between the residual vector and a Jacobian column: ~0 at a least-squares
// stationary point. Used to check fits of noisy data whose exact solution is not known.
inline double max_gradient_cosine(const Eigen::MatrixXd& J, const Eigen::VectorXd& r) {
  double worst = 0.0;
  for (Eigen::Index k = 0; k < J.cols(); ++k) {
    const double cn = J.col(k).norm();
    if (cn > 1e-12 * std::sqrt(static_cast<double>(J.rows()))) worst = std::max(worst, std::abs(J.col(k).dot(r)) / (cn * r.norm()));
  }
  return worst;
}

struct Samples3 {
  std::vector<Eigen::Vector3d> points;   // data
  std::vector<Eigen::Vector3d> feet;     // exact surface points
  std::vector<Eigen::Vector3d> normals;  // outward unit normals at the feet
};

// ---- plane -------------------------------------------------------------------------------
inline Samples3 plane_samples(Rng& rng, const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                              std::size_t n, double half_extent, double amplitude) {
  Samples3 s;
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  basis_of(normal, u, v);
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), 6);
  for (std::size_t i = 0; i < n; ++i) {
    s.feet.push_back(c + rng.uniform(-half_extent, half_extent) * u + rng.uniform(-half_extent, half_extent) * v);
    s.normals.push_back(normal);
    rigid_row(J, static_cast<Eigen::Index>(i), s.feet[i], c, normal);
  }
  const Eigen::VectorXd e = orthogonal_to(J, alternating(rng, n, amplitude));
  for (std::size_t i = 0; i < n; ++i) s.points.push_back(s.feet[i] + e(static_cast<Eigen::Index>(i)) * normal);
  return s;
}

// ---- line 3-D: deviations in two perpendicular directions, each orthogonal to [1, t] ------
inline std::vector<Eigen::Vector3d> line_samples(Rng& rng, const Eigen::Vector3d& c, const Eigen::Vector3d& dir,
                                                 std::size_t n, double length, double amplitude) {
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  basis_of(dir, u, v);
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), 2);
  Eigen::VectorXd t(static_cast<Eigen::Index>(n));
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    t(i) = rng.uniform(-0.5 * length, 0.5 * length);
    J(i, 0) = 1.0;
    J(i, 1) = t(i);
  }
  const Eigen::VectorXd e1 = orthogonal_to(J, alternating(rng, n, amplitude));
  const Eigen::VectorXd e2 = orthogonal_to(J, alternating(rng, n, amplitude));
  std::vector<Eigen::Vector3d> pts;
  for (Eigen::Index i = 0; i < t.size(); ++i) pts.push_back(c + t(i) * dir + e1(i) * u + e2(i) * v);
  return pts;
}

// ---- circle 2-D on an arc [start, start + span] ------------------------------------------------
inline std::vector<Eigen::Vector2d> circle2_samples(Rng& rng, const Eigen::Vector2d& c, double radius,
                                                    double start, double span, std::size_t n,
                                                    double amplitude) {
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), 3);
  std::vector<Eigen::Vector2d> normals;
  for (std::size_t i = 0; i < n; ++i) {
    const double th = start + span * static_cast<double>(i) / static_cast<double>(n - 1);
    normals.emplace_back(std::cos(th), std::sin(th));
    J.row(static_cast<Eigen::Index>(i)) << -normals[i].x(), -normals[i].y(), -1.0;
  }
  const Eigen::VectorXd e = orthogonal_to(J, alternating(rng, n, amplitude));
  std::vector<Eigen::Vector2d> pts;
  for (std::size_t i = 0; i < n; ++i) pts.push_back(c + (radius + e(static_cast<Eigen::Index>(i))) * normals[i]);
  return pts;
}

// ---- circle 3-D in the NIST sense: in-plane radial deviations and out-of-plane deviations, both
// balanced, so the least-squares plane is the true plane and the projected circle the true one.
inline std::vector<Eigen::Vector3d> circle3_samples(Rng& rng, const Eigen::Vector3d& c, const Eigen::Vector3d& normal,
                                                    double radius, double start, double span, std::size_t n,
                                                    double amplitude, double out_of_plane) {
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  basis_of(normal, u, v);
  const auto flat = circle2_samples(rng, Eigen::Vector2d::Zero(), radius, start, span, n, amplitude);
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), 3);
  for (std::size_t i = 0; i < n; ++i) J.row(static_cast<Eigen::Index>(i)) << 1.0, flat[i].x(), flat[i].y();
  const Eigen::VectorXd w = orthogonal_to(J, alternating(rng, n, out_of_plane));
  std::vector<Eigen::Vector3d> pts;
  for (std::size_t i = 0; i < n; ++i)
    pts.push_back(c + flat[i].x() * u + flat[i].y() * v + w(static_cast<Eigen::Index>(i)) * normal);
  return pts;
}

// ---- sphere: directions within `cap` (rad) of `pole` ------------------------------------------
inline Samples3 sphere_samples(Rng& rng, const Eigen::Vector3d& c, double radius, const Eigen::Vector3d& pole,
                               double cap, std::size_t n, double amplitude) {
  Samples3 s;
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  basis_of(pole, u, v);
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), 7);
  for (std::size_t i = 0; i < n; ++i) {
    const double polar = std::acos(1.0 - rng.uniform(0.0, 1.0) * (1.0 - std::cos(cap)));
    const double az = rng.uniform(0.0, 2.0 * kPi);
    const Eigen::Vector3d nrm = std::cos(polar) * pole + std::sin(polar) * (std::cos(az) * u + std::sin(az) * v);
    s.normals.push_back(nrm);
    s.feet.push_back(c + radius * nrm);
    rigid_row(J, static_cast<Eigen::Index>(i), s.feet[i], c, nrm);
    J(static_cast<Eigen::Index>(i), 6) = -1.0;
  }
  const Eigen::VectorXd e = orthogonal_to(J, alternating(rng, n, amplitude));
  for (std::size_t i = 0; i < n; ++i) s.points.push_back(s.feet[i] + e(static_cast<Eigen::Index>(i)) * s.normals[i]);
  return s;
}

// ---- cylinder: angular sector [0, span] about the axis, axial range [-length/2, length/2] ---
inline Samples3 cylinder_samples(Rng& rng, const Eigen::Vector3d& c, const Eigen::Vector3d& axis, double radius,
                                 double span, double length, std::size_t n, double amplitude) {
  Samples3 s;
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  basis_of(axis, u, v);
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), 7);
  for (std::size_t i = 0; i < n; ++i) {
    const double th = rng.uniform(0.0, span);
    const double h = rng.uniform(-0.5 * length, 0.5 * length);
    const Eigen::Vector3d nrm = std::cos(th) * u + std::sin(th) * v;
    s.normals.push_back(nrm);
    s.feet.push_back(c + h * axis + radius * nrm);
    rigid_row(J, static_cast<Eigen::Index>(i), s.feet[i], c, nrm);
    J(static_cast<Eigen::Index>(i), 6) = -1.0;
  }
  const Eigen::VectorXd e = orthogonal_to(J, alternating(rng, n, amplitude));
  for (std::size_t i = 0; i < n; ++i) s.points.push_back(s.feet[i] + e(static_cast<Eigen::Index>(i)) * s.normals[i]);
  return s;
}

// Signed distance and Jacobian row of a cone (NIST convention) at p; independent of the library.
inline double cone_row(const Cone& k, const Eigen::Vector3d& p, Eigen::MatrixXd* J, Eigen::Index i) {
  const Eigen::Vector3d a = k.direction.normalized();
  const double phi = 0.5 * k.apex_angle_rad;
  const Eigen::Vector3d d = p - k.point;
  const double h = d.dot(a);
  const Eigen::Vector3d radial = d - h * a;
  const double rho = radial.norm();
  if (J) {
    const Eigen::Vector3d nrm = std::cos(phi) * radial / rho - std::sin(phi) * a;
    rigid_row(*J, i, p, k.point, nrm);
    (*J)(i, 6) = -1.0;
    (*J)(i, 7) = -rho * std::sin(phi) - h * std::cos(phi);
  }
  return rho * std::cos(phi) - h * std::sin(phi) - k.distance;
}

// ---- cone: sector [0, span], axial positions h in [h0, h1] from the axis point ---------------
// The Jacobian depends on the displaced points, so the orthogonalisation is iterated.
inline Samples3 cone_samples(Rng& rng, const Cone& k, double span, double h0, double h1, std::size_t n,
                             double amplitude) {
  Samples3 s;
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  const Eigen::Vector3d a = k.direction.normalized();
  basis_of(a, u, v);
  const double phi = 0.5 * k.apex_angle_rad;
  for (std::size_t i = 0; i < n; ++i) {
    const double th = rng.uniform(0.0, span);
    const double h = rng.uniform(h0, h1);
    const Eigen::Vector3d radial = std::cos(th) * u + std::sin(th) * v;
    s.feet.push_back(k.point + h * a + k.radius_at(h) * radial);
    s.normals.push_back(std::cos(phi) * radial - std::sin(phi) * a);
  }
  const Eigen::VectorXd e0 = alternating(rng, n, amplitude);
  Eigen::VectorXd e = e0;
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), 8);
  for (int iter = 0; iter < 20; ++iter) {
    for (std::size_t i = 0; i < n; ++i)
      cone_row(k, s.feet[i] + e(static_cast<Eigen::Index>(i)) * s.normals[i], &J, static_cast<Eigen::Index>(i));
    e = orthogonal_to(J, e0);
  }
  for (std::size_t i = 0; i < n; ++i) s.points.push_back(s.feet[i] + e(static_cast<Eigen::Index>(i)) * s.normals[i]);
  return s;
}

}  // namespace imess::metrology::test
