// Basic types shared by hal, sim and the motion core: up to nine axes, millimetres or
// degrees, nanoseconds.
//
// The axis model: a machine has 1..kMaxAxes axes, each named by one letter of X Y Z A B C U
// V W, linear (mm) or rotary (degrees). Every per-axis container has the compile-time size
// kMaxAxes (nothing allocates); AxisLayout says how many are real and what they are. Entries
// at and beyond AxisLayout::count are unused and stay 0. Vec3 is Cartesian geometry only
// (probe points, approach directions): AxisLayout::cartesian takes it from the machine's
// linear X, Y and Z axes, 0 for one the machine lacks.
#pragma once
#include <Eigen/Core>
#include <array>
#include <chrono>
#include <cstdint>
#include <string>

namespace imess::hal {

inline constexpr int kMaxAxes = 9;
inline constexpr std::array<char, kMaxAxes> kAxisLetters{'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'};

using Vec3 = Eigen::Vector3d;
using AxisVec = Eigen::Matrix<double, kMaxAxes, 1>;  // machine positions, velocities, setpoints
template <class T>
using AxisArray = std::array<T, kMaxAxes>;
using Nanos = std::chrono::nanoseconds;

enum class AxisKind : std::uint8_t { Linear, Rotary };

struct AxisLayout {
  int count = 3;
  AxisArray<char> letters{'X', 'Y', 'Z'};  // machine axis i is named letters[i]
  AxisArray<AxisKind> kinds{};

  // The machine axis named letter, or -1.
  int index_of(char letter) const noexcept {
    for (int a = 0; a < count; ++a)
      if (letters[a] == letter) return a;
    return -1;
  }
  // The machine axis carrying Cartesian coordinate c (0 X, 1 Y, 2 Z): a linear axis of that
  // letter, or -1.
  int cartesian_axis(int c) const noexcept {
    const int a = index_of("XYZ"[c]);
    return a >= 0 && kinds[a] == AxisKind::Linear ? a : -1;
  }
  Vec3 cartesian(const AxisVec& p) const noexcept {
    Vec3 v = Vec3::Zero();
    for (int c = 0; c < 3; ++c)
      if (const int a = cartesian_axis(c); a >= 0) v[c] = p[a];
    return v;
  }
  // A Cartesian vector on the machine's X Y Z axes (the others 0).
  AxisVec machine(const Vec3& v) const noexcept {
    AxisVec p = AxisVec::Zero();
    for (int c = 0; c < 3; ++c)
      if (const int a = cartesian_axis(c); a >= 0) p[a] = v[c];
    return p;
  }
  // Exactly the linear axes X Y Z, in that order: the 1996 machine (every message as then).
  bool is_xyz() const noexcept {
    return count == 3 && letters[0] == 'X' && letters[1] == 'Y' && letters[2] == 'Z' &&
           kinds[0] == AxisKind::Linear && kinds[1] == AxisKind::Linear && kinds[2] == AxisKind::Linear;
  }
  // "XYCUV" (set-up code).
  std::string names() const { return std::string(letters.data(), static_cast<std::size_t>(count)); }
};

// The usual kind of a letter: A B C rotary, the others linear.
inline AxisKind default_kind(char letter) noexcept {
  return letter == 'A' || letter == 'B' || letter == 'C' ? AxisKind::Rotary : AxisKind::Linear;
}
// A layout from letters ("XYZ", "XYCUV"), every axis of its letter's usual kind. Throws
// std::invalid_argument naming the problem: 1..9 letters of XYZABCUVW, none twice.
AxisLayout make_layout(const std::string& letters);

inline double seconds(Nanos t) { return std::chrono::duration<double>(t).count(); }

// The time source of the motion loop. Real time in the daemon, virtual time in tests.
class Clock {
 public:
  virtual ~Clock() = default;
  virtual Nanos now() const noexcept = 0;
};

}  // namespace imess::hal
