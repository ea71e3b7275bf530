// `messcap convert IN OUT`: a point file (or stdin) written in the format of OUT's extension,
// optionally in a frame and with a fitted feature — the capture's writers without a machine.
#pragma once

namespace imess::messcap {

// argv[1] is "convert". Returns the exit status (0 written, 1 file error or failed fit, 2 usage).
int run_convert_command(int argc, const char* const argv[]);

}  // namespace imess::messcap
