// messoffs: 5-axis work offsets shown rotated and in a design frame, corrected there with the
// operator's confirmation, and written back as a table and a G10 L2 program (BRIEF §3).
#include <unistd.h>

#include <iostream>

#include "imess/client/usage_error.hpp"
#include "offs_command.hpp"
#include "offs_options.hpp"

int main(int argc, char* argv[]) {
  using namespace imess;
  messoffs::OffsOptions options;
  try {
    options = messoffs::parse_offs_options(argc, argv);
  } catch (const client::UsageError& e) {
    std::cerr << "messoffs: " << e.what() << "\n(try messoffs --help)\n";
    return client::kExitUsage;
  }
  if (options.help) {
    std::cout << messoffs::offs_usage();
    return client::kExitOk;
  }
  return messoffs::run_offs(options, std::cout, std::cerr, std::cin, ::isatty(STDIN_FILENO) == 1);
}
