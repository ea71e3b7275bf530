// What messoffs prints: the offsets (machine axes, rotated; in the design frame) and, for a
// correction, the offset before and after. Columns are separated by spaces, numbers have six
// decimals (nm), so the lines read back with a split on whitespace.
#pragma once
#include <optional>
#include <ostream>
#include <string>

#include <Eigen/Core>

#include "imess/metrology/five_axis.hpp"
#include "offset_table.hpp"

namespace imess::messoffs {

struct DesignChoice {
  std::string name;  // the frame's name in the store
  metrology::DesignFrame frame;
};

// The rows of `clamping` (all rows when none): rotated = Rx(-A)·Ry(-B)·base, corrected the same
// of base + correction; with a design frame a second table of the corrected offsets as points
// and their corrections as directions in that frame.
void print_offsets(std::ostream& out, const OffsetTable& table, std::optional<int> clamping,
                   const DesignChoice* design);

// One correction: as typed, as kept in the offset's axes, the [base, correction] pairs before
// and after, the rotated offset (the G10 values) before and after, and in the design frame.
void print_correction(std::ostream& out, const OffsetEntry& before, const OffsetEntry& after,
                      const Eigen::Vector3d& typed, const Eigen::Vector3d& kept, const DesignChoice* design);

}  // namespace imess::messoffs
