// --correct's AXIS=MM list.
#include "correction_spec.hpp"

#include <array>
#include <string>

#include "field_checks.hpp"
#include "imess/client/usage_error.hpp"
#include "offset_table.hpp"

namespace imess::messoffs {

Eigen::Vector3d parse_correction_spec(std::string_view text) {
  const std::string accepted = "; expected AXIS=MM pairs separated by commas, e.g. x=+0.2,z=-0.2 (axes x, y, z)";
  if (text.empty()) throw client::UsageError("--correct: empty correction" + accepted);
  Eigen::Vector3d delta = Eigen::Vector3d::Zero();
  std::array<bool, 3> seen{};
  for (std::size_t start = 0; start <= text.size();) {
    std::size_t comma = text.find(',', start);
    if (comma == std::string_view::npos) comma = text.size();
    const std::string_view item = text.substr(start, comma - start);
    start = comma + 1;
    const std::string shown = "--correct '" + std::string(item) + "'";
    if (item.size() < 3 || item[1] != '=' || (item[0] != 'x' && item[0] != 'y' && item[0] != 'z'))
      throw client::UsageError(shown + ": not AXIS=MM" + accepted);
    const auto k = static_cast<std::size_t>(item[0] - 'x');
    if (seen[k]) throw client::UsageError(shown + ": axis " + item[0] + " given twice" + accepted);
    seen[k] = true;
    try {
      delta(static_cast<Eigen::Index>(k)) = parse_number(item.substr(2), shown, "a correction in mm");
    } catch (const TableError& e) {
      throw client::UsageError(e.what() + accepted);
    }
  }
  return delta;
}

}  // namespace imess::messoffs
