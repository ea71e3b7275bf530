// `messcap convert REPORT.json [REPORT.json …] OUT.qif [--force]`: saved inspection reports
// (messcap inspect --json) as one QIF 3.0 document, one MeasurementResults per report.
#pragma once

#include <string_view>

namespace imess::messcap {

// True when convert's output (its last argument that is no option) is a .qif file.
bool converts_to_qif(int argc, const char* const argv[]);
// argv[1] is "convert". Returns the exit status (0 written, 1 a bad report or file error, 2 usage).
int run_qif_convert(int argc, const char* const argv[]);

}  // namespace imess::messcap
