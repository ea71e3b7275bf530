// The progress of a running program from its Block events. On a terminal one line redrawn in
// place, "part.nc [#########-----------]  45%  line 120  block 451/1000"; elsewhere (a
// pipe, a file) a plain line "part.nc: 45% line 120 block 451/1000", at most one a second.
#pragma once
#include <chrono>
#include <optional>
#include <string>

#include "prog_events.hpp"

namespace imess::messprog {

class ProgressView {
 public:
  using Clock = std::chrono::steady_clock;

  explicit ProgressView(bool terminal) : terminal_(terminal) {}

  // Text to write now for this block (nothing when a plain line was printed less than a second ago).
  std::string update(const BlockEvent& block, Clock::time_point now = Clock::now());
  // Before other output: removes the bar from a terminal line (empty elsewhere).
  std::string clear();
  // After other output: the last bar again (terminal only).
  std::string redraw();
  // At the program's end: the bar at 100 % when it ended ok, and the line ended.
  std::string done(bool ok);

  // The percentage of blocks done when block i of n is executing: (i - 1) / n.
  static int percent(const BlockEvent& block);
  static std::string bar(const BlockEvent& block, int percent);

 private:
  bool terminal_;
  bool shown_ = false;  // a bar is on the terminal line
  std::optional<BlockEvent> last_;
  std::optional<Clock::time_point> printed_;
};

}  // namespace imess::messprog
