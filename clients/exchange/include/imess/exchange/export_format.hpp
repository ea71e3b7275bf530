// The table from file extension to writer. Line formats (.csv .xyz .asc) are a header plus one
// line per point, so a capture can append to them; the others are written whole.
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
  // Line formats only (else nullptr): the header (may be empty) and one point's line.
  std::string (*header)();
  std::string (*point_line)(const Eigen::Vector3d&, int decimals);
  bool appendable() const { return point_line != nullptr; }
};

const std::vector<ExportFormat>& export_formats();

// By the extension of `path` (case-insensitive). Throws FormatError.
const ExportFormat& export_format_for(std::string_view path);

// ".csv, .xyz, .asc, .json, .ply, .dxf, .igs, .stp, .dmi"
std::string accepted_extensions();

}  // namespace imess::exchange
