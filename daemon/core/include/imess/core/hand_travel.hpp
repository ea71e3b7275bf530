// HandTravel: remembers where the carriage went while pushed by hand, so a hand hit gets
// the direction of the last >= 1 mm of travel (the travel itself, not its reverse).
#pragma once
#include <array>
#include <optional>

#include "imess/core/core_types.hpp"

namespace imess::core {

class HandTravel {
 public:
  static constexpr double kSpacing = 0.1;  // mm between remembered positions
  static constexpr std::size_t kDepth = 128;

  void clear() noexcept { count_ = 0; }
  void update(const Vec3& position) noexcept {
    if (count_ > 0 && (position - at(0)).norm() < kSpacing) return;
    head_ = (head_ + 1) % kDepth;
    ring_[head_] = position;
    if (count_ < kDepth) ++count_;
  }
  // Unit direction from the newest remembered position at least min_travel before hit to hit.
  std::optional<Vec3> direction_to(const Vec3& hit, double min_travel) const noexcept {
    for (std::size_t i = 0; i < count_; ++i) {
      Vec3 d = hit - at(i);
      if (d.norm() >= min_travel) return Vec3(d.normalized());
    }
    return std::nullopt;
  }

 private:
  const Vec3& at(std::size_t back) const noexcept { return ring_[(head_ + kDepth - back) % kDepth]; }
  std::array<Vec3, kDepth> ring_{};
  std::size_t head_ = 0, count_ = 0;
};

}  // namespace imess::core
