// messoffs's command line and --help text.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace imess::messoffs {

struct CorrectionRequest {
  std::string offset;     // the offset's name (G512)
  Eigen::Vector3d typed;  // as typed: in the design frame when one is chosen, else the offset's axes
  std::string text;       // "x=+0.2,z=-0.2", for the report
};

struct OffsOptions {
  std::string table;                  // .json or .csv
  std::optional<int> clamping;        // --clamping N: only this clamping
  std::optional<std::string> frame;   // --frame NAME
  std::optional<std::string> frames;  // --frames FILE
  std::vector<CorrectionRequest> corrections;
  std::optional<std::string> write_table;  // --write FILE.json
  std::optional<std::string> gcode;        // --gcode FILE
  bool yes = false;    // apply corrections without asking
  bool force = false;  // replace existing output files
  bool help = false;
};

// Throws client::UsageError naming the argument and what is accepted.
OffsOptions parse_offs_options(int argc, const char* const argv[]);
const char* offs_usage();

}  // namespace imess::messoffs
