// messprog: checks G-code, HPGL and MRM programs offline (check), draws their planned path as
// SVG (plot), and runs them on messd (run) with a progress line.
#include <iostream>

#include "check_command.hpp"
#include "imess/client/usage_error.hpp"
#include "plot_command.hpp"
#include "program_file.hpp"
#include "prog_options.hpp"
#include "run_command.hpp"

int main(int argc, char* argv[]) {
  using namespace imess;
  try {
    const messprog::ProgOptions options = messprog::parse_prog_options(argc, argv);
    if (options.help) {
      std::cout << messprog::prog_usage();
      return client::kExitOk;
    }
    switch (options.command) {
      case messprog::Command::Check: return messprog::run_check_command(options);
      case messprog::Command::Plot: return messprog::run_plot_command(options);
      case messprog::Command::Run: return messprog::run_run_command(options);
    }
  } catch (const client::UsageError& e) {
    std::cerr << "messprog: " << e.what() << "\n(try messprog --help)\n";
    return client::kExitUsage;
  } catch (const messprog::FileError& e) {
    std::cerr << "messprog: " << e.what() << "\n";
    return client::kExitFailure;
  }
  return client::kExitFailure;
}
