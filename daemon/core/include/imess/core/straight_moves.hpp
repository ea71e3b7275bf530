// StraightMoves: jog (StartMv, JogAx) and GoTo — straight lines at a path speed, every axis
// within its limits. A new one while moving brakes to rest first and starts from there (no
// axis retargeted at a fraction of its acceleration): it waits as the pending motion.
#pragma once
#include <cstdint>

#include "imess/core/loop_context.hpp"

namespace imess::core {

class StraightMoves {
 public:
  explicit StraightMoves(LoopContext& loop) noexcept : loop_(loop) {}

  Refusal jog(const AxisVec& percent, Nanos now) noexcept;
  Refusal go_to(const AxisVec& target, unsigned given, double speed, Nanos now) noexcept;

  // One cycle in Jog, Move or Stopping (state fresh): idle, or the pending motion, at rest.
  void update(Nanos now) noexcept;
  // At rest: the motion that waited for it, or idle.
  void launch_pending_or_idle(Nanos now) noexcept;
  bool pending() const noexcept { return pending_ != Pending::None; }
  void drop_pending() noexcept { pending_ = Pending::None; }

 private:
  void launch_pending(Nanos now) noexcept;
  void stand_still(Nanos now) noexcept;  // a jog of all-zero speeds
  void drop_axes_into_limits(AxisVec& v) const noexcept;
  AxisVec jog_target(const AxisVec& u) const noexcept;
  Refusal start(const AxisVec& target, const AxisVec& u, double speed, Mode mode, Nanos now) noexcept;
  // May the machine move along u while the tip is deflected? Only away from the approach
  // of the hit that deflected it.
  bool away_from_touch(const AxisVec& u) const noexcept;

  LoopContext& loop_;
  enum class Pending : std::uint8_t { None, Jog, GoTo } pending_ = Pending::None;
  AxisVec pending_v_ = AxisVec::Zero();
  unsigned pending_axes_ = ~0u;
  double pending_speed_ = 0;  // a move was commanded after this cycle's state was read
};

}  // namespace imess::core
