// The scanning methods' arguments (Shape::ScanArgs), read and written; internal to the library:
// parser.cpp reads them, format.cpp writes them (docs/ippdme.md, "Scanning").
#pragma once
#include <optional>
#include <vector>

#include "imess/ippdme/command_spec.hpp"
#include "imess/ippdme/syntax.hpp"

namespace imess::ippdme {

// Reads the arguments of the scanning method `call` names into out.built; the error the spec
// answers otherwise (0502 count or kind, 0505 a name not known there, 1010 a direction without
// norm, 0509 a value outside its domain), in that order.
std::optional<ErrorCode> read_scan_args(const Value& call, Checked& out);

// The arguments as a client writes them, numbers in their shortest form: the 1.4.3 forms, a
// plane scan without plane normal in its 1.4.0 form (parse_line reads back the same command).
std::vector<Value> scan_args(const OnScanReport& c);
std::vector<Value> scan_args(const ScanOnCircleHint& c);
std::vector<Value> scan_args(const ScanOnLineHint& c);
std::vector<Value> scan_args(const ScanUnknownHint& c);
std::vector<Value> scan_args(const ScanUnknownDensity& c);
std::vector<Value> scan_args(const ScanOnCircle& c);
std::vector<Value> scan_args(const ScanOnHelix& c);
std::vector<Value> scan_args(const ScanOnLine& c);
std::vector<Value> scan_args(const ScanInPlaneEndIsSphere& c);
std::vector<Value> scan_args(const ScanInPlaneEndIsPlane& c);
std::vector<Value> scan_args(const ScanInPlaneEndIsCyl& c);
std::vector<Value> scan_args(const ScanInCylEndIsSphere& c);
std::vector<Value> scan_args(const ScanInCylEndIsPlane& c);

}  // namespace imess::ippdme
