// Basic types shared by hal, sim and the motion core: three axes, millimetres, nanoseconds.
#pragma once
#include <Eigen/Core>
#include <array>
#include <chrono>
#include <cstdint>

namespace imess::hal {

inline constexpr int kAxes = 3;
inline constexpr std::array<char, kAxes> kAxisNames{'X', 'Y', 'Z'};

using Vec3 = Eigen::Vector3d;
template <class T>
using AxisArray = std::array<T, kAxes>;
using Nanos = std::chrono::nanoseconds;

inline double seconds(Nanos t) { return std::chrono::duration<double>(t).count(); }

// The time source of the motion loop. Real time in the daemon, virtual time in tests.
class Clock {
 public:
  virtual ~Clock() = default;
  virtual Nanos now() const noexcept = 0;
};

}  // namespace imess::hal
