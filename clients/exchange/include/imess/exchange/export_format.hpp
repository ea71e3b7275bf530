// The table from file extension to writer. Line formats (.csv .xyz .asc .hits) are a header plus
// one line per point, so a capture can append to them; the others are written whole. .hits is
// the one format that needs more than the points: each hit's approach and tip radius.
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "imess/exchange/export_data.hpp"

namespace imess::exchange {

// A file name whose extension no writer takes; the message names the file, the extension and
// lists the accepted ones.
struct FormatError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct ExportFormat {
  std::string_view extension;    // ".dxf", lower case
  std::string_view description;  // one line for --help and errors
  std::string (*write)(const ExportData&);  // the complete file
  // Line formats only (else nullptr): the header (may be empty) and one point's line —
  // point_line for formats of plain points, hit_line for .hits (which has no point_line).
  std::string (*header)();
  std::string (*point_line)(const Eigen::Vector3d&, int decimals);
  std::string (*hit_line)(const metrology::ProbedPoint&, int decimals) = nullptr;
  bool appendable() const { return point_line != nullptr || hit_line != nullptr; }
  // The format holds each hit's approach and tip radius: ExportData::hits must be given.
  bool needs_approach() const { return hit_line != nullptr; }
};

// .hits prints the surface point and the tip radius with the decimals asked for (a capture:
// kHitDecimals, the resolution of messd's Hit line) and the unit approach always with
// kApproachDecimals, as Hit does — fewer would break the readers' unit-length check.
inline constexpr int kHitDecimals = 4;
inline constexpr int kApproachDecimals = 6;

const std::vector<ExportFormat>& export_formats();

// By the extension of `path` (case-insensitive). Throws FormatError.
const ExportFormat& export_format_for(std::string_view path);

// ".csv, .xyz, .asc, .hits, .json, .ply, .dxf, .igs, .stp, .dmi"
std::string accepted_extensions();
// The line formats, for --append's refusal: ".csv, .xyz, .asc and .hits"
std::string appendable_extensions();

}  // namespace imess::exchange
