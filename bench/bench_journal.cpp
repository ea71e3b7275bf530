// bench_journal: what the hit journal costs the io thread per hit — append (format, CRC,
// write(2)), the same with fdatasync before every send, and reading back for Replay.
// Prints figures; not a test. Usage: bench_journal [DIR] (default: a new directory in /tmp).
#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "imess/journal/journal.hpp"

using namespace imess;
using Clock = std::chrono::steady_clock;

namespace {

void report(const char* what, std::vector<double>& us) {
  std::sort(us.begin(), us.end());
  double sum = 0;
  for (double v : us) sum += v;
  std::printf("%-44s n %6zu  mean %8.2f us  p50 %8.2f  p99 %8.2f  max %9.2f\n", what, us.size(), sum / double(us.size()),
              us[us.size() / 2], us[us.size() * 99 / 100], us.back());
}

double since(Clock::time_point t0) { return std::chrono::duration<double, std::micro>(Clock::now() - t0).count(); }

void run_appends(const std::string& dir, std::chrono::milliseconds fsync, int n, const char* what) {
  std::filesystem::remove_all(dir);
  journal::JournalConfig cfg{dir};
  cfg.fsync_interval = fsync;
  journal::Journal j(cfg);
  std::vector<double> us;
  for (int i = 0; i < n; ++i) {
    protocol::HitMsg h{0, 0, {430.1234, 330.5, 80 - i * 1e-3}, {0.6, 0, -0.8}, 2, 1234.5 + i};
    auto t0 = Clock::now();
    j.append(h);
    j.sync_if_due();  // what the io thread does after each event drain
    us.push_back(since(t0));
  }
  report(what, us);
}

}  // namespace

int main(int argc, char** argv) {
  std::string dir = argc > 1 ? argv[1] : "";
  if (dir.empty()) {
    std::string pattern = (std::filesystem::temp_directory_path() / "bench-journal-XXXXXX").string();
    if (!mkdtemp(pattern.data())) return 1;
    dir = pattern;
  }
  run_appends(dir + "/a", std::chrono::milliseconds(100), 100000, "append, fsync every 100 ms (default)");
  run_appends(dir + "/b", std::chrono::milliseconds(0), 2000, "append + fdatasync every hit (fsync_ms 0)");
  {
    journal::Journal j({dir + "/a"});
    std::vector<double> us;
    for (std::uint64_t from : {1ull, 20000ull, 40000ull, 60000ull, 80000ull, 99001ull}) {
      auto t0 = Clock::now();
      auto r = j.read(from, 1000);
      us.push_back(since(t0));
      if (r.lines.empty()) std::printf("Replay %llu read nothing\n", static_cast<unsigned long long>(from));
    }
    report("Replay of 1000 hits (read + check)", us);
  }
  std::filesystem::remove_all(dir);
}
