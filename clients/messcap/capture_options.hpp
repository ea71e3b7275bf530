// messcap's command line.
#pragma once
#include <optional>
#include <string>

#include "imess/client/endpoint.hpp"
#include "point_file.hpp"

namespace imess::messcap {

inline constexpr int kMaxCount = 1000000;

struct CaptureOptions {
  client::Endpoint endpoint;
  std::optional<int> count;           // -n N; none = open-ended
  std::optional<std::string> output;  // -o FILE (.csv or .xyz, checked here)
  OpenMode mode = OpenMode::New;
  bool help = false;
};

// Throws client::UsageError naming the bad argument and what is accepted; an output file with
// an unknown extension is rejected here, before anything connects.
CaptureOptions parse_capture_options(int argc, const char* const argv[]);

std::string capture_usage();

}  // namespace imess::messcap
