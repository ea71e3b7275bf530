// The motion law of one segment along its path: s(t), a piecewise polynomial in t (at most
// seven pieces, each with constant jerk). Built here: the trapezoid (three pieces, jerk 0).
// A jerk-limited seven-phase profile fills the same struct and nothing else changes.
#pragma once
#include <array>

namespace imess::planner {

// One piece: from its start time on, s = s0 + v0·τ + a0·τ²/2 + j·τ³/6 (τ: time into the piece).
struct ProfilePiece {
  double t0 = 0, duration = 0;
  double s0 = 0, v0 = 0, a0 = 0, j = 0;
};

struct PathState {
  double s = 0, v = 0, a = 0;  // along the path: length, speed, acceleration
};

struct Profile {
  static constexpr int kMaxPieces = 7;
  std::array<ProfilePiece, kMaxPieces> pieces{};
  int count = 0;
  double duration = 0;  // s; sum of the pieces' durations
  double length = 0;    // L; at(t ≥ duration).s is exactly this

  // s, v, a at time t (clamped to [0, duration]; at the end exactly length and the exit speed).
  PathState at(double t) const noexcept;
};

// The trapezoid from v0 through at most vc to v1 over length L with acceleration a (> 0):
// accelerate, cruise, decelerate; a triangle when L is too short to reach vc.
// Expects |v1² − v0²| ≤ 2aL (look-ahead guarantees it; a rounding excess is absorbed).
struct Trapezoid {
  double v0 = 0, vc = 0, v1 = 0, a = 0;
  double t_acc = 0, t_cruise = 0, t_dec = 0;
};
Trapezoid plan_trapezoid(double length, double v0, double vc_max, double v1, double a) noexcept;
Profile trapezoid_profile(double length, const Trapezoid& t) noexcept;
// A pause of the given duration at s = 0 (dwell, zero-length move: duration 0).
Profile rest_profile(double duration) noexcept;

}  // namespace imess::planner
