// messprog check: figures on stdout (with --canon LinuxCNC's canonical calls instead) and exit
// 0, or the program's first error on stderr and exit 1.
#include "check_command.hpp"

#include <iostream>

#include "check_report.hpp"
#include "dry_run.hpp"
#include "imess/programs/canon.hpp"
#include "program_file.hpp"

namespace imess::messprog {

int run_check_command(const ProgOptions& options) {
  const DryRun d = dry_run(options);
  if (!d.check.ok) return report_program_error(options, d.check);
  if (options.canon) {
    const auto t = programs::translate(options.lang, read_program(options.file), d.setup);
    std::cout << programs::canonical_program(t, d.machine, d.setup.start);
    return 0;
  }
  std::cout << check_report(options.file, options.lang, d.check, d.machine, d.description);
  return 0;
}

}  // namespace imess::messprog
