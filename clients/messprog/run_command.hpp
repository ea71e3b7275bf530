// messprog run FILE [HOST[:PORT]]: the program sent to messd and run, with its progress.
#pragma once
#include "prog_options.hpp"

namespace imess::messprog {

int run_run_command(const ProgOptions& options);

}  // namespace imess::messprog
