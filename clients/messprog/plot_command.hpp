// messprog plot FILE -o OUT.svg: the dry run drawn as SVG.
#pragma once
#include "prog_options.hpp"

namespace imess::messprog {

int run_plot_command(const ProgOptions& options);

}  // namespace imess::messprog
