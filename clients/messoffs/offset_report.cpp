// The printed tables and the before/after of a correction.
#include "offset_report.hpp"

#include <cstdio>

#include "design_view.hpp"
#include "imess/exchange/export_data.hpp"

namespace imess::messoffs {
namespace {

using exchange::fixed;

std::string pad(const std::string& s, std::size_t width) {
  return s.size() < width ? s + std::string(width - s.size(), ' ') : s;
}

std::string right(const std::string& s, std::size_t width) {
  return s.size() < width ? std::string(width - s.size(), ' ') + s : s;
}

std::string cell(double v, std::size_t width, int decimals = 6) { return right(" " + fixed(v, decimals), width); }

std::string cells(const Eigen::Vector3d& v) { return cell(v.x(), 12) + cell(v.y(), 12) + cell(v.z(), 12); }

std::string p_text(const OffsetEntry& e) { return e.p ? std::to_string(*e.p) : std::string("-"); }

std::string label(const OffsetEntry& e) {
  return e.name + " (clamping " + std::to_string(e.clamping) + ", P" + p_text(e) + ")";
}

}  // namespace

void print_offsets(std::ostream& out, const OffsetTable& table, std::optional<int> clamping,
                   const DesignChoice* design) {
  out << "work offsets in machine axes (mm, degrees); rotated = Rx(-A)*Ry(-B)*base, corrected = "
         "Rx(-A)*Ry(-B)*(base + correction)\n";
  out << "clamping offset    P         A         B |   rotated x           y           z |"
         " corrected x           y           z\n";
  for (const auto& e : table.rows) {
    if (clamping && e.clamping != *clamping) continue;
    out << right(std::to_string(e.clamping), 8) << " " << pad(e.name, 8) << right(p_text(e), 3)
        << cell(e.offset.a_deg, 10, 3) << cell(e.offset.b_deg, 10, 3) << " |" << cells(e.offset.rotated_base())
        << " |" << cells(e.offset.rotated()) << "\n";
  }
  if (!design) return;
  out << "\nin design frame '" << design->name
      << "': offsets as points T*(p - w_MKS) + w_KKS, corrections as directions T*d\n";
  out << "clamping offset   | corrected x           y           z |correction x           y           z\n";
  for (const auto& e : table.rows) {
    if (clamping && e.clamping != *clamping) continue;
    out << right(std::to_string(e.clamping), 8) << " " << pad(e.name, 8) << " |"
        << cells(design->frame.point_to_design(e.offset.rotated())) << " |"
        << cells(correction_to_design(e.offset.correction(), e.offset, design->frame)) << "\n";
  }
}

void print_correction(std::ostream& out, const OffsetEntry& before, const OffsetEntry& after,
                      const Eigen::Vector3d& typed, const Eigen::Vector3d& kept, const DesignChoice* design) {
  out << "\ncorrection of " << label(before)
      << (design ? " in design frame '" + design->name + "':" : std::string(" in the offset's axes:")) << cells(typed)
      << "\n";
  if (design) out << "  kept in the offset's axes:" << cells(kept) << "\n";
  out << "  axis        base   correction before   correction after\n";
  const char* axes[] = {"x", "y", "z"};
  for (std::size_t k = 0; k < 3; ++k)
    out << "  " << axes[k] << "   " << cell(before.offset.axis[k].base, 12) << cell(before.offset.axis[k].correction, 20)
        << cell(after.offset.axis[k].correction, 19) << "\n";
  out << "  before (rotated, the G10 values):" << cells(before.offset.rotated()) << "\n";
  out << "  after  (rotated, the G10 values):" << cells(after.offset.rotated()) << "\n";
  if (design) {
    out << "  before in design frame:          " << cells(design->frame.point_to_design(before.offset.rotated())) << "\n";
    out << "  after  in design frame:          " << cells(design->frame.point_to_design(after.offset.rotated())) << "\n";
  }
}

}  // namespace imess::messoffs
