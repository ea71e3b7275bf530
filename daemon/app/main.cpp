// messd: the controller daemon. Reads the configuration, brings up the controller (the
// simulated CMM unless configured otherwise), starts the motion loop and serves TCP.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <boost/asio.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "cli.hpp"
#include "config.hpp"
#include "fd_limit.hpp"
#include "imess/core/event_fd.hpp"
#include "imess/core/loop_runner.hpp"
#include "imess/core/motion_core.hpp"
#include "imess/journal/journal.hpp"
#include "imess/net/server.hpp"
#include "json_object.hpp"
#include "machine.hpp"
#include "version.hpp"

using namespace imess;

namespace {

app::DaemonConfig configure(const app::CliOptions& cli) {
  app::DaemonConfig cfg;
  if (cli.config)
    app::load_json_config(*cli.config, cfg);
  else
    cfg.notes.push_back("no --config given: the built-in simulated CMM with the 1996 worked example");
  std::optional<std::string> rc = cli.rc;
  if (!rc && std::filesystem::exists("messdrc")) rc = "messdrc";  // the 1996 place
  if (rc)
    for (const auto& w : app::load_messdrc(*rc, cfg)) spdlog::warn("{}", w);
  if (cli.port) cfg.server.port = static_cast<std::uint16_t>(*cli.port);
  if (cli.listen) cfg.server.listen = *cli.listen;
  if (cli.ippdme_port) {
    cfg.server.ippdme.on = *cli.ippdme_port != 0;
    cfg.server.ippdme.port = static_cast<std::uint16_t>(*cli.ippdme_port);
  } else if (cli.port && *cli.port == 0 && cfg.server.ippdme.on) {
    cfg.server.ippdme.port = 0;  // a test's messd: any free port for both, so many can run at once
  }
  if (cli.http_port) {
    cfg.server.web.on = *cli.http_port != 0;
    cfg.server.web.port = static_cast<std::uint16_t>(*cli.http_port);
  } else if (cli.port && *cli.port == 0 && cfg.server.web.on) {
    cfg.server.web.port = 0;  // as the I++ DME port
  }
  if (cli.journal) cfg.journal.dir = *cli.journal;
  if (cli.programs) cfg.server.programs.folder = std::filesystem::absolute(*cli.programs).lexically_normal().string();
  if (cfg.journal.dir.empty()) cfg.journal.dir = app::default_journal_dir();
  if (cli.frames) cfg.server.frames_file = *cli.frames;
  if (cfg.server.frames_file.empty()) cfg.server.frames_file = app::default_state_file("frames.json", "messd-frames.json");
  if (cli.device) {
    if (cfg.backend != "servo-card")
      throw app::ConfigError("--device names the servo card's serial device; it is for backend.type \"servo-card\", not \"" +
                             cfg.backend + "\"");
    cfg.card_line.device = *cli.device;
    cfg.notes.push_back("--device: the card on " + *cli.device);
  }
  if (cli.home) cfg.home_on_start = true;
  if (cli.no_realtime) cfg.realtime = false;
  cfg.server.log_traffic = cli.debug_comm;
  cfg.server.log_motion = cli.debug_motion;
  cfg.server.log_status = cli.debug_status;
  cfg.server.log_timing = cli.timing;
  cfg.server.version = app::kVersion;
  app::finish_config(cfg);
  return cfg;
}

// The command line into cli; the exit status when messd ends here (--help, --version, a
// bad argument), nullopt when it goes on.
std::optional<int> read_command_line(int argc, char** argv, app::CliOptions& cli) {
  try {
    cli = app::parse_cli(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "messd: " << e.what() << "\n" << app::usage_text();
    return 2;
  }
  if (cli.help) {
    std::cout << app::usage_text();
    return 0;
  }
  if (cli.version) {
    std::cout << "messd " << app::kVersion << " (IMESS interactive measuring machine controller)\n";
    return 0;
  }
  return std::nullopt;
}

// What the motion loop got: a warning when real-time scheduling was refused.
void log_realtime(const std::string& rt) {
  if (rt.find("not permitted") != std::string::npos)
    spdlog::warn("{}", rt);
  else
    spdlog::info("{}", rt);
}

// Fewer clients when the descriptor limit cannot hold max_clients (a warning then).
void fit_clients_to_fd_limit(net::ServerConfig& server) {
  auto fds = app::fit_fd_limit(server.max_clients);
  if (fds.message.empty()) return;
  if (fds.lowered)
    spdlog::warn("{}", fds.message);
  else
    spdlog::info("{}", fds.message);
  server.max_clients = fds.max_clients;
}

void log_control_rules(const net::ServerConfig& server) {
  const auto& rules = server.control;
  spdlog::info("control from {}; observe from {}; forced take-over from {}; {} of {} slots kept for control hosts",
               rules.hosts.to_string(), rules.observe_hosts.to_string(), rules.force_hosts.to_string(),
               std::min(rules.reserved_slots, server.max_clients - 1), server.max_clients);
}

// The configuration into cfg, its notes logged; false (logged) when it cannot be used.
bool load_configuration(const app::CliOptions& cli, app::DaemonConfig& cfg) {
  try {
    cfg = configure(cli);
  } catch (const std::exception& e) {  // ConfigError, and anything a reader did not foresee
    spdlog::error("{}", e.what());
    return false;
  }
  for (const auto& n : cfg.notes) spdlog::info("{}", n);
  spdlog::info("TipRadius {:.3f} mm, SpeedLevel {:.3f}, TipReversed {}", cfg.core.params.tip_radius,
               cfg.core.params.speed_level, cfg.card.tip_reversed ? "true" : "false");
  return true;
}

// The hit journal, its start-up notes logged; nullptr (logged) when it cannot be opened.
std::unique_ptr<journal::Journal> open_journal(const journal::JournalConfig& config) {
  std::unique_ptr<journal::Journal> hits;
  try {
    hits = std::make_unique<journal::Journal>(config);
  } catch (const journal::JournalError& e) {
    spdlog::error("{}", e.what());
    return nullptr;
  }
  for (const auto& n : hits->notes()) spdlog::info("{}", n);
  for (const auto& w : hits->warnings()) spdlog::warn("{}", w);
  return hits;
}

// The configured machine, initialised; nullptr (logged) when it does not start, with the
// exit status: 2 for settings the backend cannot run (a configuration error), else 1.
std::unique_ptr<app::Machine> start_controller(const app::DaemonConfig& cfg, const hal::Clock& clock,
                                               bool reboot, int& exit_status) {
  std::unique_ptr<app::Machine> machine;
  try {
    machine = app::make_machine(cfg, clock, reboot);
  } catch (const app::ConfigError& e) {  // settings the backend cannot run: fix the file first
    spdlog::error("controller start failed: {}", e.what());
    exit_status = 2;
    return nullptr;
  } catch (const std::exception& e) {
    spdlog::error("controller start failed: {}", e.what());
    exit_status = 1;
    return nullptr;
  }
  spdlog::info("controller: {}", machine->describe());
  return machine;
}

// Says "OK, listening" on stdout (what scripts wait for) and runs the io thread until SIGINT
// or SIGTERM.
void serve_until_signal(boost::asio::io_context& io, net::Server& server, const net::ServerConfig& config) {
  boost::asio::signal_set signals(io, SIGINT, SIGTERM);
  signals.async_wait([&](boost::system::error_code, int sig) {
    spdlog::info("signal {}: stopping", sig);
    server.stop();
    io.stop();
  });
  std::printf("messd: OK, listening on %s:%u\n", config.listen.c_str(), static_cast<unsigned>(server.port()));
  if (server.ipp_port())
    std::printf("messd: I++ DME on %s:%u\n", config.listen.c_str(), static_cast<unsigned>(server.ipp_port()));
  else
    std::printf("messd: I++ DME off\n");
  if (server.web_port())
    std::printf("messd: web panel on http://%s:%u/ (files from %s)\n", config.listen.c_str(),
                static_cast<unsigned>(server.web_port()), server.web_root().c_str());
  else
    std::printf("messd: web panel off\n");
  std::fflush(stdout);
  io.run();
}

// At exit: every axis brakes with its configured deceleration, the loops open, the base
// thread ends.
void stop_machine(core::MotionCore& core, app::Machine& machine) {
  hal::AxisVec decel = hal::AxisVec::Zero();
  for (int a = 0; a < core.config().layout.count; ++a) decel[a] = core.config().axes[a].max_accel;
  machine.backend().stop(decel);
  machine.backend().set_loops(false);
  machine.stop_base_thread();
}

// The daemon's life; main() around it turns any exception that escapes into a message and
// exit status 2, so no input can end messd in an abort.
int run(int argc, char** argv) {
  auto logger = spdlog::stderr_color_mt("messd");
  spdlog::set_default_logger(logger);
  spdlog::set_pattern("%H:%M:%S.%e messd %^%l%$: %v");

  app::CliOptions cli;
  if (auto status = read_command_line(argc, argv, cli)) return *status;

  app::DaemonConfig cfg;
  if (!load_configuration(cli, cfg)) return 2;
  auto hits = open_journal(cfg.journal);  // before the machine: every hit must have a place to go
  if (!hits) return 2;
  core::MonotonicClock clock;
  core::LoopClock loop_clock(clock.now());  // sim.time "loop": the machine's and the core's time
  const hal::Clock& machine_clock = cfg.sim_loop_time ? static_cast<const hal::Clock&>(loop_clock) : clock;
  int failed = 1;
  auto machine = start_controller(cfg, machine_clock, cli.reboot, failed);
  if (!machine) return failed;

  core::MotionCore core(machine->backend(), cfg.core, machine->sim_hooks());
  core::EventFd wake;  // the loop wakes the io thread through it when it pushed events
  core.set_event_signal(&wake);
  core.start(machine_clock.now());
  core::LoopRunner runner(core, clock, std::chrono::nanoseconds(static_cast<long>(cfg.period_us * 1000)));
  if (cfg.sim_loop_time) {
    runner.use_loop_time(&loop_clock, cfg.sim_speed);
    spdlog::info("sim.time loop: the simulated machine's clock moves one period per motion cycle (host stalls pause it){}",
                 cfg.sim_speed > 1 ? fmt::format(", {} times as fast as the wall clock (sim.speed)", cfg.sim_speed) : "");
  }
  log_realtime(runner.start(cfg.realtime));

  if (auto base = machine->start_base_thread(cfg.realtime); !base.empty()) spdlog::info("{}", base);

  fit_clients_to_fd_limit(cfg.server);
  log_control_rules(cfg.server);

  boost::asio::io_context io;
  net::Server server(io, cfg.server, core, &runner, *hits, &wake);
  try {
    server.start();
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    runner.stop();
    return 1;
  }
  if (cfg.home_on_start) {
    spdlog::info("reference search requested at start");
    core.submit(core::Command{core::CommandKind::Home});
  }
  serve_until_signal(io, server, cfg.server);

  runner.stop();
  stop_machine(core, *machine);
  spdlog::info("motion stopped, loops open; bye");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "messd: stopped by an unexpected error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "messd: stopped by an unexpected error of unknown type\n");
  }
  return 2;
}
