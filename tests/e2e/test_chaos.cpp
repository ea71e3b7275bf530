// Chaos: messd is killed with SIGKILL at random (seeded) moments of a measuring loop and
// restarted on the same journal and port, while messcap --reconnect records. In the end the
// capture holds every journaled hit exactly once, in order, and the journal has no gap.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <thread>

#include "child_process.hpp"
#include "daemon_process.hpp"
#include "imess/journal/record.hpp"
#include "imess/protocol/messages.hpp"

using namespace imess::test;
using Clock = std::chrono::steady_clock;

namespace {

constexpr int kKills = 12;
constexpr unsigned kSeed = 20261123;

struct Point {
  std::uint64_t seq;
  double x, y, z;
};

// Jogs into the cube top, comes back up, measures a few points by ForcePt — again and again
// until the deadline, whatever state the machine is in; replies are not waited for.
void measure_until(LineClient& c, Clock::time_point deadline) {
  auto left = [&] { return std::chrono::duration<double>(deadline - Clock::now()).count(); };
  auto wait_idle = [&] {
    while (left() > 0) {
      auto l = c.next(std::min(left(), 0.2));
      if (l && *l == "State idle") return true;
      if (!l && c.closed()) return false;
    }
    return false;
  };
  while (left() > 0) {
    c.send("StartMv 0 0 -100");
    if (!wait_idle()) return;  // hit, retract, idle
    c.send("GoTo 430 330 95");
    if (!wait_idle()) return;
    for (int i = 0; i < 5; ++i) c.send("ForcePt");
  }
}

std::vector<Point> journal_points(const std::string& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".jnl") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<Point> out;
  for (const auto& f : files) {
    std::ifstream in(f);
    std::string line;
    while (std::getline(in, line)) {
      auto r = imess::journal::decode_record(line);
      INFO(f << ": " << line);
      REQUIRE(r);
      auto h = std::get<imess::protocol::HitMsg>(imess::protocol::parse_message(r->wire));
      out.push_back({h.seq, h.p.x, h.p.y, h.p.z});
    }
  }
  return out;
}

std::vector<Point> capture_points(const std::string& path) {
  std::vector<Point> out;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    Point p{};
    std::string hash, word;
    s >> p.x >> p.y >> p.z >> hash >> word >> p.seq;
    INFO(line);
    REQUIRE((hash == "#" && word == "hit"));
    out.push_back(p);
  }
  return out;
}

std::uint64_t last_seq_in(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line)) last = line;
  auto at = last.rfind(' ');
  return at == std::string::npos ? 0 : std::stoull(last.substr(at + 1));
}

}  // namespace

TEST_CASE("chaos: SIGKILL at random moments while measuring loses no hit and duplicates none", "[long]") {
  const auto started = Clock::now();
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> run_for(0.3, 1.5);
  TempDir dir;
  const std::string journal = dir.file("journal"), capture = dir.file("capture.xyz");
  const std::vector<std::string> base{"--config", std::string(IMESS_SOURCE_DIR) + "/tests/e2e/fast-cmm.json",
                                      "--journal", journal};
  auto messd = std::make_unique<DaemonProcess>(base);
  const std::string port = std::to_string(messd->port());
  auto with_port = base;
  with_port.insert(with_port.end(), {"--port", port, "--ippdme-port", "0", "--http-port", "0"});
  ChildProcess cap({client_binary("messcap"), "127.0.0.1:" + port, "-o", capture, "--reconnect"});
  // A new capture takes the hits journaled after it connected: let it connect first.
  for (auto until = Clock::now() + std::chrono::seconds(5); cap.err().find("connected to") == std::string::npos;) {
    REQUIRE(Clock::now() < until);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // its start probe answered

  for (int k = 0; k <= kKills; ++k) {
    {
      LineClient driver(messd->port());
      measure_until(driver, Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                               std::chrono::duration<double>(run_for(rng))));
    }
    if (k == kKills) break;  // the last round ends without a kill
    messd->stop(SIGKILL);
    messd = std::make_unique<DaemonProcess>(with_port);
  }

  // The newest hit journaled, as messd says (after the driver's last commands have run);
  // then wait for messcap to hold it.
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  std::uint64_t newest = 0;
  {
    LineClient c(messd->port());
    c.send("Replay 999999999");
    auto ok = c.until_prefix("Ok Replay", 5.0);
    REQUIRE(ok);
    newest = std::stoull(ok->substr(ok->rfind(' ') + 1));
  }
  const auto catch_up = Clock::now() + std::chrono::seconds(15);
  while (last_seq_in(capture) < newest && Clock::now() < catch_up) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  cap.signal(SIGTERM);
  auto status = cap.wait(5s);
  INFO("messcap stderr:\n" << cap.err());
  REQUIRE(status == 0);

  auto journaled = journal_points(journal);
  auto captured = capture_points(capture);
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  // How many hits messcap had to fetch with Replay (measured while it was reconnecting).
  std::size_t replayed = 0;
  std::istringstream err(cap.err());
  for (std::string l; std::getline(err, l);)
    if (l.rfind("messcap: Replay gave ", 0) == 0) replayed += std::stoul(l.substr(21));
  WARN("chaos: " << kKills << " kills, " << journaled.size() << " hits (" << replayed << " of them sent again by Replay), "
                 << seconds << " s");
  REQUIRE(journaled.size() >= 30);
  CHECK(journaled.back().seq == newest);
  for (std::size_t i = 0; i < journaled.size(); ++i) REQUIRE(journaled[i].seq == i + 1);  // gap-free from 1
  REQUIRE(captured.size() == journaled.size());
  for (std::size_t i = 0; i < captured.size(); ++i) {
    INFO("capture line " << i + 1);
    REQUIRE(captured[i].seq == journaled[i].seq);
    CHECK(std::abs(captured[i].x - journaled[i].x) < 0.0011);
    CHECK(std::abs(captured[i].y - journaled[i].y) < 0.0011);
    CHECK(std::abs(captured[i].z - journaled[i].z) < 0.0011);
  }
}
