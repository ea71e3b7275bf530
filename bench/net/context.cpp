// Starting the servers a figure measures, and the random request phases.
#include "context.hpp"

#include <filesystem>
#include <fstream>

#include "client_pool.hpp"
#include "clock.hpp"

namespace imess::bench {

Context::Context(const Options& options, Report& report) : options_(options), report_(report), rng_(options.seed), tmp_("bench-net") {}

std::unique_ptr<ServerProcess> Context::start_messd(int clients, const std::string& machine) {
  ClientPool::reserve_descriptors(static_cast<std::size_t>(clients) + 16);
  if (external_messd()) return std::make_unique<ServerProcess>(options_.port, options_.pid);
  const std::string dir = tmp_.path() + "/messd-" + std::to_string(++started_);
  std::filesystem::create_directories(dir + "/journal");
  // Loopback clients may all control (control.hosts), so reserved_slots takes nothing from
  // them; idle_drop_s long enough that an owner waiting between samples is never dropped, and
  // no no_command_drop_s: the benchmark's receiving clients never send a command.
  std::ofstream(dir + "/config.json") << R"({ "server": { "max_clients": )" << clients + 16
                                      << R"(, "ippdme_port": 0 }, "control": { "idle_drop_s": 86400, "no_command_drop_s": 0 })"
                                      << (machine.empty() ? "" : ", " + machine) << " }\n";
  std::vector<std::string> args{"--config", dir + "/config.json", "--journal", dir + "/journal", "--frames", dir + "/frames.json",
                                "--port", "0", "--listen", "127.0.0.1"};
  if (!options_.realtime) args.push_back("--no-rt");
  const std::string path = options_.messd.empty() ? own_bin_dir() + "/messd" : options_.messd;
  last_log_ = dir + "/messd.log";
  auto p = std::make_unique<ServerProcess>(path, args, last_log_);
  note("started " + path + " (pid " + std::to_string(p->pid()) + ", port " + std::to_string(p->port()) + ", max_clients " +
       std::to_string(clients + 16) + (options_.realtime ? ", real-time if permitted)" : ", --no-rt)"));
  return p;
}

std::unique_ptr<ServerProcess> Context::start_echo(const std::string& mode, double hz) {
  const std::string dir = tmp_.path();
  std::vector<std::string> args{"--mode", mode, "--port", "0"};
  if (mode == "timer") {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", hz);
    args.insert(args.end(), {"--hz", buf});
  }
  const std::string path = options_.echo.empty() ? own_bin_dir() + "/bench_echo" : options_.echo;
  return std::make_unique<ServerProcess>(path, args, dir + "/echo-" + std::to_string(++started_) + ".log");
}

std::string Context::last_messd_log(std::size_t bytes) const {
  if (last_log_.empty()) return {};
  std::ifstream f(last_log_);
  std::string log((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  return log.size() > bytes ? "..." + log.substr(log.size() - bytes) : log;
}

void Context::random_phase() {
  std::uniform_int_distribution<std::int64_t> phase(0, 2'000'000);
  sleep_until_ns(mono_ns() + phase(rng_));
}

}  // namespace imess::bench
