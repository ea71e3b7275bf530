// G10 L2 lines for the work offsets of one clamping.
#include "gcode_program.hpp"

#include "imess/exchange/export_data.hpp"

namespace imess::messoffs {

std::string gcode_number(double value) {
  std::string s = exchange::fixed(value, 6);
  while (s.back() == '0' && s[s.size() - 2] != '.') s.pop_back();
  if (s == "-0.0") s = "0.0";
  return s;
}

std::string offset_program(const OffsetTable& table, int clamping, const std::string& source) {
  std::string body;
  for (const auto& e : table.rows) {
    if (e.clamping != clamping) continue;
    if (!e.p)
      throw TableError("offset '" + e.name + "' (clamping " + std::to_string(clamping) +
                       ") has no P number for G10 L2: give it a \"p\" (1..9 = G54..G59.3) in the table");
    const Eigen::Vector3d v = e.offset.rotated();
    body += "G10 L2 P" + std::to_string(*e.p) + " X" + gcode_number(v.x()) + " Y" + gcode_number(v.y()) + " Z" +
            gcode_number(v.z()) + " (" + e.name + " A" + gcode_number(e.offset.a_deg) + " B" +
            gcode_number(e.offset.b_deg) + ")\n";
  }
  if (body.empty()) throw TableError("clamping " + std::to_string(clamping) + " has no offsets in the table");
  std::string file_name = source.substr(source.rfind('/') == std::string::npos ? 0 : source.rfind('/') + 1);
  for (char& c : file_name)
    if (c == '(' || c == ')') c = '_';  // G-code comments do not nest
  return "(work offsets of clamping " + std::to_string(clamping) + " from " + file_name + ", written by messoffs)\n" +
         "(values: Rx(-A)*Ry(-B)*(base + correction), mm)\n" + "G21\n" + body + "M2\n";
}

}  // namespace imess::messoffs
