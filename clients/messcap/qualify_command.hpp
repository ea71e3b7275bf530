// `messcap qualify HOST[:PORT] --sphere X,Y,Z --diameter D [--points N] [--rc FILE] [--json OUT]
// [--max-form MM] [--feed MM_S]`: qualifies the probe on a reference sphere (docs/clients.md).
#pragma once

#include <string>

namespace imess::messcap {

// Exit status of a qualification refused by its limits (form error above --max-form, a radius
// or an offset messd cannot hold): messd keeps its values; the report is written all the same.
inline constexpr int kExitNotQualified = 5;

// argv[1] is "qualify". Returns 0 qualified, 1 a connection, probing, fit or file error, 2 bad
// arguments, 5 refused by the limits.
int run_qualify_command(int argc, const char* const argv[]);

std::string qualify_usage();

}  // namespace imess::messcap
