// DaemonConfig: everything messd is set up from — defaults, then the JSON configuration,
// then the 1996 messdrc, then the command line.
#pragma once
#include <string>
#include <vector>

#include "imess/core/core_types.hpp"
#include "imess/hal/serial_card_link.hpp"
#include "imess/hal/servo_card_driver.hpp"
#include "imess/journal/journal_config.hpp"
#include "imess/net/server.hpp"
#include "imess/sim/simulated_cmm.hpp"
#include "port_backend_config.hpp"

namespace imess::app {

// messd's server: the library's defaults, and the web panel on 8080 (docs/web.md).
inline net::ServerConfig daemon_server_config() {
  net::ServerConfig s;
  s.web.on = true;
  return s;
}

struct DaemonConfig {
  net::ServerConfig server = daemon_server_config();
  core::CoreConfig core;
  double period_us = 1000;
  bool realtime = true;        // try SCHED_FIFO + mlockall
  bool home_on_start = false;
  std::string backend = "sim-servo-card";
  hal::ServoCardConfig card;
  hal::SerialLinkSettings card_line;  // "servo-card": the card's serial device and baud rate
  PortBackendConfig ports;  // parport / drive-kit backends (port_backend_config.hpp; read in backend_config.cpp)
  // The built-in machine's card streams over a simulated 115 200 baud line (it rides out host
  // stalls shorter than the lead); "link": "request-reply" in the backend section chooses the other.
  sim::SimulatedCmmConfig sim = [] {
    sim::SimulatedCmmConfig s;
    s.streamed = true;
    return s;
  }();
  journal::JournalConfig journal;  // dir empty: default_journal_dir()
  bool sim_probe_nc_set = false;  // sim.probe.normally_closed given explicitly
  bool sim_loop_time = false;     // sim.time "loop": the machine's clock moves one period per cycle
  int sim_speed = 1;              // sim.speed: in loop time, cycles this many times a period of wall time
  bool outputs_given = false;     // an "outputs" section was read (else the backend's default)
  std::vector<std::string> notes;  // what was read from where, for the start-up log
};

// Reads a JSON configuration file over the defaults; throws ConfigError naming file and key
// (also for a file that is missing, a directory, unreadable or empty).
void load_json_config(const std::string& path, DaemonConfig& config);
// The same for JSON text already in memory; `file` is the name used in messages.
void load_config_text(const std::string& text, const std::string& file, DaemonConfig& config);

// Reads a 1996 messdrc (SpeedLevel, TipReversed, TipRadius, # comments). Unknown lines are
// returned as warnings; a bad or repeated value, or an empty file, throws ConfigError
// naming file and line.
std::vector<std::string> load_messdrc(const std::string& path, DaemonConfig& config);
std::vector<std::string> load_messdrc_text(const std::string& text, const std::string& file, DaemonConfig& config);

// The journal's directory when neither --journal nor the configuration names one:
// $STATE_DIRECTORY/journal (systemd's StateDirectory=), else ./messd-journal.
std::string default_journal_dir();
// $STATE_DIRECTORY/<name> under systemd, else `fallback` (relative to the working directory).
std::string default_state_file(const std::string& name, const std::string& fallback);

// Derives what follows from other settings (sim axes from the travel, probe polarity, the
// server's read-only Period and Backend).
void finish_config(DaemonConfig& config);

}  // namespace imess::app
