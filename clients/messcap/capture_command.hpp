// Live capture: MeasPt lines from messd, each printed and written to the file the moment it
// arrives, optionally in a frame, with a fit of all points when the capture ends.
#pragma once

namespace imess::messcap {

// Returns the exit status (docs/clients.md).
int run_capture(int argc, const char* const argv[]);

}  // namespace imess::messcap
