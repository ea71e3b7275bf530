// The two measurements of bench_rt. Each adds its figures to the report; false when it could
// not run at all (messd did not start), with the reason on stderr.
#pragma once
#include "options.hpp"
#include "report.hpp"
#include "temp_dir.hpp"

namespace imess::bench {

bool run_loop(const Options& options, Report& report);  // loop_bench.cpp
bool run_base(const Options& options, Report& report);  // base_bench.cpp

}  // namespace imess::bench
