// What every figure runner shares: the options, the report, the random phases, and the
// servers it measures — a messd configured for the clients it needs (or the running one of
// --port/--pid) and bench_echo, the loopback floor, in the mode the figure compares with.
#pragma once
#include <memory>
#include <random>
#include <string>

#include "options.hpp"
#include "report.hpp"
#include "server_process.hpp"

namespace imess::bench {

class Context {
 public:
  Context(const Options& options, Report& report);

  const Options& options() const { return options_; }
  Report& report() { return report_; }
  bool quick() const { return options_.quick; }

  // messd serving at least `clients` connections: started here (--no-rt unless --rt, port 0,
  // a temporary config with server.max_clients, journal and frames in a temporary
  // directory), or the one of --port/--pid.
  // machine: more members of the configuration's top level (JSON text, "" for none), e.g. a
  // measuring probe's "sim" and "backend" sections.
  std::unique_ptr<ServerProcess> start_messd(int clients, const std::string& machine = "");
  // bench_echo in mode echo, broadcast or timer (hz: the timer's rate).
  std::unique_ptr<ServerProcess> start_echo(const std::string& mode, double hz = 0);
  bool external_messd() const { return options_.port != 0; }

  // A random phase: sleeps a uniform 0 … 2 ms, so requests do not fall into step with
  // messd's 1 ms loop or its timers.
  void random_phase();
  std::mt19937& rng() { return rng_; }
  // The end of the log of the messd started last (empty: none started here), for errors.
  std::string last_messd_log(std::size_t bytes = 1500) const;

 private:
  const Options& options_;
  Report& report_;
  std::mt19937 rng_;
  TempDir tmp_;
  int started_ = 0;
  std::string last_log_;
};

}  // namespace imess::bench
