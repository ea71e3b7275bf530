// `messcap inspect PLAN [--points FILE | HOST[:PORT]] [--json OUT] [--html OUT] [--qif OUT]
// [--operator NAME] [--feed MM_S]`:
// nominal-versus-actual inspection of a part by an inspection plan (docs/clients.md).
#pragma once

#include <string>

namespace imess::messcap {

// Exit status of a finished inspection with characteristics outside their tolerance or not
// evaluated (the reports are written all the same).
inline constexpr int kExitOutOfTolerance = 5;

// argv[1] is "inspect". Returns the exit status: 0 every characteristic in tolerance, 1 a file,
// connection, probing or alignment error, 2 bad arguments, 5 out of tolerance / not evaluated.
int run_inspect_command(int argc, const char* const argv[]);

std::string inspect_usage();

}  // namespace imess::messcap
