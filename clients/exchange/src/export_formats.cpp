// The extension → writer table, and the lookup that turns a file name into its format.
#include <algorithm>
#include <cctype>
#include <ctime>

#include "imess/exchange/export_format.hpp"
#include "writers.hpp"

namespace imess::exchange {

const std::vector<ExportFormat>& export_formats() {
  using namespace writers;
  static const std::vector<ExportFormat> table = {
      {".csv", "header 'x,y,z', then one 'x,y,z' line per point", csv, csv_header, csv_line},
      {".xyz", "one 'x y z' line per point", xyz, xyz_header, xyz_line},
      {".asc", "one 'x y z' line per point (FreeCAD's ASCII point cloud)", xyz, xyz_header, xyz_line},
      {".hits", "one 'x y z i j k r' line per hit: surface point, approach, tip radius", hits, hits_header, nullptr,
       hits_line},
      {".json", "{\"units\":\"mm\",\"points\":[[x,y,z],...]} plus \"fit\" with --fit", json, nullptr, nullptr},
      {".ply", "ASCII PLY, one vertex (double x y z) per point", ply, nullptr, nullptr},
      {".dxf", "DXF R12 (AC1009), POINT entities on layer IMESS_POINTS", dxf, nullptr, nullptr},
      {".igs", "IGES 5.3, entity 116 (point) per point, fixed 80-column records", iges, nullptr, nullptr},
      {".stp", "STEP AP214, CARTESIAN_POINTs in a GEOMETRIC_CURVE_SET", step, nullptr, nullptr},
      {".dmi", "DMIS: POINT features with MEAS blocks, or with --fit the fitted feature (F, MEAS, FA)", dmis,
       nullptr, nullptr},
  };
  return table;
}

std::string accepted_extensions() {
  std::string out;
  for (const auto& f : export_formats()) {
    if (!out.empty()) out += ", ";
    out += f.extension;
  }
  return out;
}

std::string appendable_extensions() {
  std::vector<std::string_view> line_formats;
  for (const auto& f : export_formats())
    if (f.appendable()) line_formats.push_back(f.extension);
  std::string out;
  for (std::size_t i = 0; i < line_formats.size(); ++i)
    out += std::string(i == 0 ? "" : i + 1 == line_formats.size() ? " and " : ", ") + std::string(line_formats[i]);
  return out;
}

const ExportFormat& export_format_for(std::string_view path) {
  auto slash = path.rfind('/');
  auto name = slash == std::string_view::npos ? path : path.substr(slash + 1);
  auto dot = name.rfind('.');
  std::string ext = dot == std::string_view::npos ? "" : std::string(name.substr(dot));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const auto& f : export_formats())
    if (f.extension == ext) return f;
  throw FormatError("output file '" + std::string(path) + "': " +
                    (ext.empty() ? std::string("no extension") : "unknown extension '" + ext + "'") +
                    "; accepted: " + accepted_extensions());
}

namespace writers {

std::string local_timestamp(const char* format) {
  std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char buf[40];
  std::strftime(buf, sizeof buf, format, &tm);
  return buf;
}

std::string real_with_point(double v, int decimals) {
  std::string s = fixed(v, decimals);
  if (s.find('.') == std::string::npos) s += '.';
  return s;
}

}  // namespace writers
}  // namespace imess::exchange
