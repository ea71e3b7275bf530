// `messcap fit KIND [FILE | -]`: fits one feature with imess::metrology and prints it as one
// JSON object (fields in docs/clients.md).
#pragma once

namespace imess::messcap {

// argv[1] is "fit". Returns the exit status (0 fitted, 1 file error or failed fit, 2 usage).
int run_fit_command(int argc, const char* const argv[]);

}  // namespace imess::messcap
