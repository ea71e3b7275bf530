// The writers behind the extension table (one file each: export_<format>.cpp).
#pragma once
#include <string>

#include "imess/exchange/export_data.hpp"

namespace imess::exchange::writers {

std::string csv_header();
std::string csv_line(const Eigen::Vector3d& p, int decimals);
std::string csv(const ExportData& d);

std::string xyz_header();
std::string xyz_line(const Eigen::Vector3d& p, int decimals);
std::string xyz(const ExportData& d);

std::string hits_header();
std::string hits_line(const metrology::ProbedPoint& h, int decimals);
std::string hits(const ExportData& d);  // throws FormatError when d.hits does not match d.points

std::string json(const ExportData& d);
std::string ply(const ExportData& d);
std::string dxf(const ExportData& d);
std::string iges(const ExportData& d);
std::string step(const ExportData& d);
std::string dmis(const ExportData& d);

// A real number as STEP and IGES write it: `decimals` places, always with a decimal point
// ("12." rather than "12").
std::string real_with_point(double v, int decimals);

// "2024-05-01T14:03:07" in local time, for the headers that carry a date.
std::string local_timestamp(const char* format = "%Y-%m-%dT%H:%M:%S");

}  // namespace imess::exchange::writers
