// OffsetTable: the zero-offset table messoffs reads, corrects and writes — per offset its
// clamping, name, G10 P number and a metrology::WorkOffset ([base, correction] per axis, A, B).
#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "imess/metrology/five_axis.hpp"

namespace imess::messoffs {

// A table that cannot be used; the message names the file, the line or key and what is accepted.
struct TableError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int kMinP = 1;  // G10 L2 P1..P9: LinuxCNC's G54..G59.3
inline constexpr int kMaxP = 9;

struct OffsetEntry {
  int clamping = 1;        // the set-up this offset belongs to (1, 2, ...)
  std::string name;        // as the operator knows it: G510, G54, ...
  std::optional<int> p;    // the G10 L2 P number its values are written to
  metrology::WorkOffset offset;
};

struct OffsetTable {
  std::vector<OffsetEntry> rows;

  // The row of `name` in `clamping` (any clamping when none is given). Throws TableError when
  // there is none, or when the name is in several clampings and none was chosen.
  OffsetEntry& find(std::string_view name, std::optional<int> clamping);
  std::vector<int> clampings() const;  // ascending, each once
};

// Names are letters, digits, '.', '_' and '-' (they go into G-code comments and CSV fields).
bool valid_offset_name(std::string_view name);
// G54..G59 -> 1..6, G59.1..G59.3 -> 7..9 (LinuxCNC); any other name has no implied P number.
std::optional<int> implied_p(std::string_view name);

// Whole-table rules: at least one offset, a name once per clamping, a P number once per
// clamping. Throws TableError "<source>: ..." naming the offsets that clash.
void check_table(const OffsetTable& table, std::string_view source);

}  // namespace imess::messoffs
