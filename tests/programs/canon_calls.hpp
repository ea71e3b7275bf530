// LinuxCNC canonical calls (rs274 -g's text, or ours) read back as numbers for comparison:
// the motions in program units, each feed move with its speed in mm/min as LinuxCNC's canon
// converts it (SET_FEED_RATE in the units in force when it is called), moves that go nowhere dropped.
#pragma once
#include <string>
#include <vector>

namespace imess::programs::test {

struct Motion {
  std::string name;          // STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, STRAIGHT_PROBE, DWELL
  std::vector<double> args;  // as printed, lengths in mm (ARC_FEED's rotation as it is)
  double feed_mm = 0;        // feed moves: mm/min (deg/min)
  double tolerance = 0.00015;  // half a printed digit and more, in mm
};

std::vector<Motion> motions(const std::string& text);

// "" when both lists agree (positions within 1.5 of the last printed digit, feeds within
// 0.003 mm/min), else the first difference in words.
std::string difference(const std::vector<Motion>& ours, const std::vector<Motion>& theirs);

}  // namespace imess::programs::test
