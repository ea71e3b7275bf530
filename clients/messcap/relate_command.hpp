// `messcap relate [A B | -]`: distance and angle between two fitted features, each given as the
// JSON object `messcap fit` prints; prints one JSON object (docs/metrology.md §12.1).
#pragma once
#include <string>

namespace imess::messcap {

// argv[1] is "relate". Returns the exit status (0 related, 1 unreadable or unusable input, 2 usage).
int run_relate_command(int argc, const char* const argv[]);

std::string relate_usage();

}  // namespace imess::messcap
