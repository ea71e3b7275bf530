// One messoffs run: load, show, correct (confirmed), write; returns the exit status.
#pragma once
#include <istream>
#include <ostream>

#include "offs_options.hpp"

namespace imess::messoffs {

// `answers` is where the confirmation is read from when `interactive` (a terminal on stdin).
int run_offs(const OffsOptions& options, std::ostream& out, std::ostream& err, std::istream& answers,
             bool interactive);

}  // namespace imess::messoffs
