// messcap's command line: live capture (the default) and its shared output options.
#pragma once
#include <optional>
#include <string>

#include "imess/client/endpoint.hpp"
#include "imess/exchange/fit_report.hpp"
#include "point_file.hpp"

namespace imess::messcap {

inline constexpr int kMaxCount = 1000000;

// What capture and convert share: where the points go and how they are written.
struct OutputOptions {
  std::optional<std::string> output;       // -o FILE / convert's OUT; extension checked on parsing
  OpenMode mode = OpenMode::New;
  std::optional<std::string> frame;        // --frame NAME
  std::optional<std::string> frames_file;  // --frames FILE
  std::optional<exchange::FitKind> fit;    // --fit KIND
  bool outer = false;                      // --outer (DMIS side of the fitted feature)
};

struct CaptureOptions {
  client::Endpoint endpoint;
  std::optional<int> count;  // -n N; none = open-ended
  OutputOptions out;
  bool reconnect = false;  // --reconnect: wait for messd to come back, fetch what was missed
  bool help = false;
};

// Throws client::UsageError naming the bad argument and what is accepted; an output file with
// an unknown extension is rejected here, before anything connects.
CaptureOptions parse_capture_options(int argc, const char* const argv[]);

// Tries the options capture and convert share at argv[i] (--frame, --frames, --fit, --outer,
// --append, --force); true when it took argv[i] (and maybe its value). Throws UsageError.
bool parse_output_option(OutputOptions& o, int& i, int argc, const char* const argv[]);
// The cross-checks after all arguments: --frame needs --frames, --append vs --force, ...
void check_output_options(OutputOptions& o, bool append, bool force);
void check_output_file(const std::string& path);  // extension known; throws UsageError

std::string capture_usage();

}  // namespace imess::messcap
