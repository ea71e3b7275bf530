// messprog check FILE: the offline check and its report.
#pragma once
#include "prog_options.hpp"

namespace imess::messprog {

int run_check_command(const ProgOptions& options);

}  // namespace imess::messprog
