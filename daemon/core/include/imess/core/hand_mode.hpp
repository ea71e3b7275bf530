// HandMode: the machine with its loops open, pushed by hand (or, simulated, by HandMv). It
// remembers the travel while free (HandTravel, forgotten each time the loop enters Free) and
// turns a probe edge into a hand hit compensated along the last >= HandTravel mm of travel.
#pragma once
#include <cstdint>

#include "imess/core/hand_travel.hpp"
#include "imess/core/loop_context.hpp"

namespace imess::core {

class HandMode {
 public:
  explicit HandMode(LoopContext& loop) noexcept : loop_(loop) {}

  // HandMv: the simulator pushes the carriage (refused on real hardware and with loops closed).
  Refusal push(const Command& c) noexcept;
  // One cycle in Free: remember where the carriage is.
  void track() noexcept;
  // A probe edge with the loops open (Free or Fault): a compensated point, or a warning why not.
  void hit(const AxisVec& latched, Nanos now) noexcept;

 private:
  void forget_if_free_again() noexcept;  // the travel before the loop last entered Free is not this push's

  LoopContext& loop_;
  HandTravel travel_;
  std::uint32_t free_entries_ = 0;  // LoopContext::free_entries when the travel was started
  Nanos last_hit_{-1'000'000'000'000};
};

}  // namespace imess::core
