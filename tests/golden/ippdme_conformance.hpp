// The I++ DME conformance replay (tests/golden/ippdme-conformance/README.md): a command file is
// a golden-format script (inputs only) whose `#? ` comment lines say what the spec requires of
// the answers. `check_conformance` replays it and returns every rule it breaks — the framing
// rules on every line, and each expectation.
#pragma once
#include <set>
#include <string>
#include <vector>

#include "transcript.hpp"

namespace imess::golden {

struct ConformanceReport {
  std::vector<std::string> failures;   // empty: the file conforms
  std::set<std::string> methods;       // every method name the I++ client sent
  std::set<int> expected_errors;       // every error number a `#? … error NNNN` asks for
  std::vector<std::string> received;   // the I++ client's lines, for a failure's context
};

// The framing rules and the expectations of `script` against what the I++ client (client 2)
// received in `replayed` (the script replayed by the golden harness).
ConformanceReport check_conformance(const std::vector<Entry>& script, const std::vector<Entry>& replayed);

// Two payloads equal but for numbers, which may differ by `tolerance` (a position read after a
// move carries the servo's following error).
bool near_payload(const std::string& expected, const std::string& actual, double tolerance);

}  // namespace imess::golden
