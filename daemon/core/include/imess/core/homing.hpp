// Homing: the reference search of 1996, axis by axis — out of a limit if needed, search the
// home switch fast, back off and search again if it came too soon, leave it slowly to the
// encoder index, creep across the index and put its centre at the axis' home position.
#pragma once
#include "imess/core/core_types.hpp"
#include "imess/hal/motion_backend.hpp"

namespace imess::core {

class Homing {
 public:
  enum class Result { Running, Done, Failed };

  void begin(const CoreConfig& config, Nanos now) noexcept;
  // One motion cycle; ms is this cycle's machine state. Allocation-free.
  Result step(const hal::MachineState& ms, hal::MotionBackend& hw, Nanos now) noexcept;
  const char* failure() const noexcept { return failure_; }
  int axis() const noexcept { return axis_; }

 private:
  enum class Phase { Start, EscapeLimit, Search, SearchStopping, BackOff, LeaveSwitch, IndexStopping, CreepBack, Creep, CreepStopping };

  struct Sense;

  void enter(Phase p, Nanos now) noexcept { phase_ = p; phase_start_ = now; }
  // One step per phase (homing.cpp); each returns Running, Done or a failure.
  Result start_axis(const hal::MachineState& ms, hal::MotionBackend& hw, Nanos now) noexcept;
  Result search(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept;
  Result after_search(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept;
  Result leave_switch(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept;
  Result creep(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept;
  Result set_home(const Sense& s, hal::MotionBackend& hw, Nanos now) noexcept;
  // Starts a move of the homed axis and enters the next phase; a refused move fails homing.
  Result go(hal::MotionBackend& hw, double target, double speed, Phase next, Nanos now) noexcept;
  Result search_from(hal::MotionBackend& hw, double pos, Nanos now) noexcept;
  bool jog(hal::MotionBackend& hw, double target, double speed) noexcept;
  void brake(hal::MotionBackend& hw) noexcept;  // every axis, configured deceleration
  Result fail(const char* why) noexcept { failure_ = why; return Result::Failed; }

  const CoreConfig* config_ = nullptr;
  Phase phase_ = Phase::Start;
  Nanos phase_start_{0}, search_start_{0};
  int order_pos_ = 0, axis_ = 0, dir_ = -1;
  bool backed_off_ = false, reversed_ = false, prev_index_ = false;
  double entry_ = 0, exit_ = 0;
  bool have_entry_ = false;
  const char* failure_ = "";
};

}  // namespace imess::core
