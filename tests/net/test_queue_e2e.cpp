// Queued moves end to end through net::Server in virtual time: a loopback TCP client sends
// MoveTo / ArcTo / Dwell / Queue / Pause / StopMv; the Server plans on the io side, the motion
// core (on the IdealFollower double) follows; the test steps the loop and reads the lines.
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <linux/sockios.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "ideal_follower.hpp"
#include "imess/core/event_fd.hpp"
#include "imess/journal/journal.hpp"
#include "imess/net/server.hpp"

using namespace imess;

namespace {

class TempDir {
 public:
  TempDir() {
    path_ = (std::filesystem::temp_directory_path() / "imess-queue-XXXXXX").string();
    if (!mkdtemp(path_.data())) throw std::runtime_error("mkdtemp failed");
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

journal::JournalConfig jconfig(const std::string& dir) {
  journal::JournalConfig c;
  c.dir = dir;
  return c;
}

net::ServerConfig sconfig() {
  net::ServerConfig c;
  c.listen = "127.0.0.1";
  c.port = 0;
  c.ippdme.port = 0;  // any free port: tests run side by side
  c.stream_position = false;
  return c;
}

// The Server and the core in virtual time, one client; the golden harness's approach.
class QueueHarness {
 public:
  QueueHarness() : journal_(jconfig(dir_.path())), server_(io_, sconfig(), rig.core(), nullptr, journal_, &wake_) {
    spdlog::set_level(spdlog::level::off);
    rig.core().set_event_signal(&wake_);
    server_.start();
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(server_.port());
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    REQUIRE(::connect(fd_, reinterpret_cast<sockaddr*>(&to), sizeof to) == 0);
    int one = 1;
    setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (lines_.empty() && std::chrono::steady_clock::now() < limit) settle();  // CurrCor on connect
  }
  ~QueueHarness() {
    if (fd_ >= 0) ::close(fd_);
    server_.stop();
    quiet();
  }

  // Sends lines in one write, lets the io side answer, runs one cycle.
  void send(const std::string& text) {
    std::string b = text + "\n";
    REQUIRE(::send(fd_, b.data(), b.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(b.size()));
    settle();
    step();
  }
  void step() {
    rig.clock().advance(test::MotionRig::kPeriod);
    rig.core().cycle(rig.clock().now());
    settle();
  }
  void run(double seconds) {
    for (long i = 0, n = static_cast<long>(seconds * 1000 + 0.5); i < n; ++i) step();
  }
  bool run_until(const std::string& line, double seconds) {
    for (long i = 0, n = static_cast<long>(seconds * 1000); i < n; ++i) {
      if (has(line)) return true;
      step();
    }
    return has(line);
  }
  bool has(const std::string& line) const {
    for (auto& l : lines_)
      if (l == line) return true;
    return false;
  }
  std::vector<std::string> starting(const std::string& prefix) const {
    std::vector<std::string> out;
    for (auto& l : lines_)
      if (l.rfind(prefix, 0) == 0) out.push_back(l);
    return out;
  }
  const std::vector<std::string>& lines() const { return lines_; }
  // The controlling client goes away (its connection closes).
  void disconnect() {
    ::close(fd_);
    fd_ = -1;
    quiet();
  }
  void clear() { lines_.clear(); }

  struct Rig : test::MotionRig {
    Rig() { start_core(test::FollowerRig::default_config()); }
    hal::MotionBackend& backend() override { return hw; }
    test::IdealFollower hw;
  } rig;

 private:
  void quiet() {
    do io_.restart();
    while (io_.poll() > 0);
  }
  void settle() {
    if (fd_ < 0) {
      quiet();
      return;
    }
    for (int i = 0; i < 1000; ++i) {
      int unacked = 0;
      if (ioctl(fd_, SIOCOUTQ, &unacked) != 0 || unacked == 0) break;
      quiet();
    }
    quiet();
    char buf[65536];
    for (;;) {
      auto n = ::recv(fd_, buf, sizeof buf, MSG_DONTWAIT);
      if (n <= 0) break;
      pending_.append(buf, static_cast<std::size_t>(n));
    }
    for (auto nl = pending_.find('\n'); nl != std::string::npos; nl = pending_.find('\n')) {
      lines_.push_back(pending_.substr(0, nl));
      pending_.erase(0, nl + 1);
    }
  }

  TempDir dir_;
  core::EventFd wake_;
  journal::Journal journal_;
  boost::asio::io_context io_;
  net::Server server_;
  int fd_ = -1;
  std::string pending_;
  std::vector<std::string> lines_;
};

}  // namespace

TEST_CASE("MoveTo, ArcTo and Dwell through the Server: Ok, State move, Done in order, idle at the end") {
  QueueHarness h;
  h.send("MoveTo 1 X150 F50\nMoveTo 2 Y150\nArcTo 3 CW X200 Y200 I50\nDwell 4 0.1\nMoveTo 5 Z50 X210 F40");
  CHECK(h.has("Ok MoveTo"));
  CHECK(h.starting("Ok ").size() == 5);
  CHECK(h.has("Ok ArcTo"));
  CHECK(h.has("Ok Dwell"));
  CHECK(h.has("State move"));
  REQUIRE(h.run_until("Done 5", 20));
  CHECK(h.starting("Done ") == std::vector<std::string>{"Done 1", "Done 2", "Done 3", "Done 4", "Done 5"});
  CHECK(h.starting("Failed").empty());
  h.step();
  CHECK(h.has("State idle"));
  CHECK(h.rig.position().isApprox(hal::Vec3(210, 200, 50), 1e-9));
  // the arc ran on its circle: centre (200, 150) = start + I, radius 50, a quarter turn CW, every followed point within 1 µm
  int on_arc = 0;
  for (const auto& sp : h.rig.hw.setpoints) {
    const double x = sp.position.x(), y = sp.position.y();
    if (x > 150 + 1e-6 && y > 150 + 1e-6 && x < 200 - 1e-6 && y < 200 - 1e-6 && std::abs(sp.position.z() - 100) < 1e-9) {
      CHECK(std::abs(std::hypot(x - 200, y - 150) - 50) < 1e-6);
      ++on_arc;
    }
  }
  CHECK(on_arc > 100);
}

TEST_CASE("a MoveTo out of the travel is Err 206 naming the id and the axis — nothing moves") {
  QueueHarness h;
  h.send("MoveTo 42 Y900");
  CHECK(h.has("Err 206 segment 42: axis Y leaves its travel at 900.000000"));
  h.run(0.1);
  CHECK(h.starting("Done").empty());
  CHECK(h.rig.hw.follow_calls == 0);
  h.send("Queue");
  CHECK(h.has("Ok Queue Pending 0 Running none Held no"));
}

TEST_CASE("StopMv mid-queue: Ok StopMv, every queued id Failed Stopped, then a new queue runs") {
  QueueHarness h;
  h.send("MoveTo 1 X400 F80\nMoveTo 2 Y300\nMoveTo 3 X100");
  h.run(0.5);
  h.send("Queue");
  CHECK(h.has("Ok Queue Pending 3 Running 1 Held no"));
  h.send("StopMv");
  CHECK(h.has("Ok StopMv"));
  REQUIRE(h.run_until("State idle", 2));
  // In the order they were queued: the ids the loop held fail there a cycle after those the
  // planner still held fail on the io side, and those wait for them.
  CHECK(h.starting("Failed ") == std::vector<std::string>{"Failed 1 Stopped a stop dropped the queue",
                                                          "Failed 2 Stopped a stop dropped the queue",
                                                          "Failed 3 Stopped a stop dropped the queue"});
  const auto failed = h.starting("Failed ");
  CHECK(h.starting("Done").empty());
  for (const auto& l : failed) CHECK(l.size() <= 78);
  h.clear();
  h.send("MoveTo 7 X120");  // starts where the machine came to rest
  CHECK(h.has("Ok MoveTo"));
  CHECK(h.run_until("Done 7", 10));
  CHECK(h.starting("Failed").empty());
}

TEST_CASE("StopMv with ids in the loop and ids still planned: every Failed in the order queued") {
  QueueHarness h;
  h.send("MoveTo 5 X400 F50\nMoveTo 6 Y300\nMoveTo 7 X300\nMoveTo 8 Y200\nMoveTo 9 X200\nMoveTo 10 Y100");
  h.run(0.3);
  h.send("StopMv");
  REQUIRE(h.run_until("State idle", 2));
  std::vector<std::string> expected;
  for (int id = 5; id <= 10; ++id) expected.push_back("Failed " + std::to_string(id) + " Stopped a stop dropped the queue");
  CHECK(h.starting("Failed ") == expected);
}

TEST_CASE("Pause holds the queue on its path, Queue says Held yes, Resume finishes it") {
  QueueHarness h;
  h.send("MoveTo 1 X300 Y250 F60");
  h.run(1.0);
  h.send("Pause");
  CHECK(h.has("Ok Pause"));
  h.run(0.5);
  const auto held = h.rig.position();
  h.run(0.3);
  CHECK(h.rig.position() == held);
  h.send("Queue");
  CHECK(h.has("Ok Queue Pending 1 Running 1 Held yes"));
  h.send("Resume");
  CHECK(h.has("Ok Resume"));
  CHECK(h.run_until("Done 1", 10));
}

TEST_CASE("a GoTo while a queue runs is Err 202 — MoveTo while jogging is Err 202") {
  QueueHarness h;
  h.send("MoveTo 1 X300 F50");
  h.run(0.2);
  h.send("GoTo 0 0 0");
  CHECK(h.starting("Err 202").size() == 1);
  CHECK(h.run_until("Done 1", 10));
  h.run(0.01);
  h.clear();
  h.send("StartMv 10 0 0");
  h.run(0.05);
  h.send("MoveTo 2 X100");
  CHECK(h.starting("Err 202").size() == 1);
}

TEST_CASE("a backend that cannot follow: MoveTo is Ok, then Failed id Faulted") {
  QueueHarness h;
  h.rig.hw.can_follow = false;
  h.send("MoveTo 9 X120");
  h.run(0.1);
  const auto failed = h.starting("Failed 9 Faulted");
  CHECK(failed.size() == 1);
  CHECK(h.starting("Done").empty());
}

TEST_CASE("the controlling client disconnects mid-queue: the machine brakes and the queue is dropped") {
  QueueHarness h;
  h.send("MoveTo 1 X400 F80\nMoveTo 2 Y300\nMoveTo 3 X100");
  h.run(0.5);
  REQUIRE(h.rig.mode() == test::Mode::Path);
  const int stops = h.rig.hw.stops;
  h.disconnect();
  h.run(0.3);
  CHECK(h.rig.hw.stops == stops + 1);
  CHECK(h.rig.mode() == test::Mode::Idle);
  CHECK_FALSE(h.rig.core().snapshot().path_running);
  const auto at_rest = h.rig.position();
  h.run(1.0);  // nothing of the dropped queue runs later
  CHECK(h.rig.position() == at_rest);
  CHECK(h.rig.position().y() == 100);  // segment 2 never started
}

TEST_CASE("ArcTo in the ZX plane (I K) with a helix along Y and P2 turns: on the circle, counter-clockwise about +Y") {
  QueueHarness h;
  // machine at 100 100 100; centre (110, ·, 100), radius 10: half a circle plus one full turn, Y rises 10
  h.send("ArcTo 1 CCW X120 Y110 I10 K0 P2 F30");
  CHECK(h.has("Ok ArcTo"));
  REQUIRE(h.run_until("Done 1", 20));
  h.step();
  CHECK(h.rig.position().isApprox(hal::Vec3(120, 110, 100), 1e-9));
  const auto& sp = h.rig.hw.setpoints;
  REQUIRE(sp.size() > 500);
  double y_prev = 100, swept = 0, a_prev = std::atan2(0.0, -10.0);
  for (const auto& p : sp) {
    const double dx = p.position.x() - 110, dz = p.position.z() - 100;
    CHECK(std::hypot(dx, dz) == Approx(10).margin(1e-6));
    CHECK(p.position.y() >= y_prev - 1e-9);  // the helix rises monotonically
    y_prev = p.position.y();
    // counter-clockwise about +Y turns Z toward X: the angle atan2(x, z)... measured as atan2(-dz, dx) grows
    const double a = std::atan2(-dz, dx);
    swept += std::remainder(a - a_prev, 2 * 3.14159265358979323846);
    a_prev = a;
  }
  CHECK(swept == Approx(3 * 3.14159265358979323846).margin(1e-6));  // 1.5 turns, positive about +Y
  CHECK(sp[20].position.z() > 100);                                   // from -X about +Y: Z rises first
}

TEST_CASE("ArcTo in the YZ plane (J K) and in a tilted plane (N i j k): on the circle and in the plane") {
  QueueHarness h;
  h.send("ArcTo 1 CW Y120 J10 K0 F30\nArcTo 2 CCW X120 Y120 Z80 I10 J0 K-10 N 1 0 1 F30");
  CHECK(h.starting("Ok ArcTo").size() == 2);
  REQUIRE(h.run_until("Done 2", 20));
  h.step();
  CHECK(h.rig.position().isApprox(hal::Vec3(120, 120, 80), 1e-9));
  int in_first = 0, in_second = 0;
  for (const auto& p : h.rig.hw.setpoints) {
    const hal::Vec3 q = p.position.head<3>();
    if (std::abs(q.x() - 100) < 1e-12 && q.y() > 100 + 1e-9 && q.y() < 120 - 1e-9) {  // the YZ half circle
      CHECK(std::hypot(q.y() - 110, q.z() - 100) == Approx(10).margin(1e-6));
      CHECK(q.z() > 100 - 1e-9);  // CW seen from +X, from 9 o'clock (-Y) up through 12 (+Z)
      ++in_first;
    } else if (q.x() > 100 + 1e-9 && q.x() < 120 - 1e-9) {  // the tilted half circle, centre (110, 120, 90)
      const hal::Vec3 r = q - hal::Vec3(110, 120, 90);
      CHECK(q.y() < 120 + 1e-9);  // counter-clockwise about N from (-1, 0, 1): through -Y
      CHECK(r.norm() == Approx(std::sqrt(200.0)).margin(1e-6));
      CHECK((r.x() + r.z()) / std::sqrt(2.0) == Approx(0).margin(1e-6));  // in the plane of N 1 0 1
      ++in_second;
    }
  }
  CHECK(in_first > 100);
  CHECK(in_second > 100);
}

TEST_CASE("ArcTo refusals name what was wrong and what is accepted — nothing is queued") {
  QueueHarness h;
  const std::pair<const char*, const char*> cases[] = {
      {"ArcTo 4 CW X110 I5 J5 K5",
       "Err 105 ArcTo 4: I J K together need N i j k, the plane's normal; I J is the XY plane, I K the ZX plane, J K "
       "the YZ plane"},
      {"ArcTo 4 CW Z110 K5",
       "Err 105 ArcTo 4: K alone names no plane; give I K (ZX plane) or J K (YZ plane), with I0 or J0 if need be, or N "
       "i j k"},
      {"ArcTo 4 CW X120 I10 P0",
       "Err 105 ArcTo 4: P is the number of turns, a whole number from 1 (the arc alone) to 1000, got 0"},
      {"ArcTo 4 CW X120 I10 P2.5",
       "Err 105 ArcTo 4: P is the number of turns, a whole number from 1 (the arc alone) to 1000, got 2.5"},
      {"ArcTo 4 CW X120 I10 N 0 0 0", "Err 105 segment 4: arc plane normal must be a finite non-zero vector"},
      {"ArcTo 4 CCW X120 Z105 I10 N 0 0 1",
       "Err 105 segment 4: arc end is 5.000000 off the plane through the start (accepted: up to 0.010000; a planar arc "
       "has no helix)"},
      {"ArcTo 4 CW X130 I10",
       "Err 105 segment 4: arc end is not on the circle: its radius differs from the start's by 10.000000 (accepted: up "
       "to 0.010000)"},
      {"ArcTo 4 CW X110 I0 J0", "Err 105 segment 4: arc centre lies on the start point: the radius must be > 0"},
      {"ArcTo 4 CW X120 I10 N 0 0",
       "Err 101 ArcTo takes N alone followed by three numbers (N i j k), got 'N'; usage: ArcTo id dir X.. Y.. Z.. I.. "
       "J.. K.. N i j k P.. F.."},
      {"ArcTo 4 CW X120 I10 N0 0 1",
       "Err 101 ArcTo takes N alone followed by three numbers (N i j k), got 'N0'; usage: ArcTo id dir X.. Y.. Z.. I.. "
       "J.. K.. N i j k P.. F.."},
      {"ArcTo 4 CW X120 I10 N 0 x 1",
       "Err 102 'x' is not a number; usage: ArcTo id dir X.. Y.. Z.. I.. J.. K.. N i j k P.. F.. (decimal numbers, "
       "e.g. -12.5)"},
      // both ends inside the travel (0 ... 500), the circle bulges below Z 0 clockwise about +Y
      {"ArcTo 5 CW X340 I120 K0", "Err 206 segment 5: axis Z leaves its travel at -20.000000"},
  };
  for (const auto& [line, reply] : cases) {
    INFO(line);
    h.clear();
    h.send(line);
    CHECK(h.has(reply));
  }
  h.run(0.1);
  CHECK(h.rig.hw.follow_calls == 0);
  h.send("Queue");
  CHECK(h.has("Ok Queue Pending 0 Running none Held no"));
  h.send("ArcTo 6 CCW X340 I120 K0");  // the same arc the other way round stays inside (Z up to 220)
  CHECK(h.has("Ok ArcTo"));
  REQUIRE(h.run_until("Done 6", 30));
}

TEST_CASE("ArcTo: the session of docs/protocol.md (\"Arcs\") line for line") {
  QueueHarness h;
  h.send("ArcTo 1 CCW X120 Y110 I10 K0 P2 F30");
  CHECK(h.has("Ok ArcTo"));
  REQUIRE(h.run_until("Done 1", 20));
  h.send("ArcTo 2 CW Y130 J10 K0 F30\nArcTo 3 CCW X140 Z80 I10 K-10 N 1 0 1 F30");
  CHECK(h.starting("Ok ArcTo").size() == 3);
  REQUIRE(h.run_until("Done 3", 20));
  CHECK(h.starting("Done") == std::vector<std::string>{"Done 1", "Done 2", "Done 3"});
  h.step();
  CHECK(h.rig.position().isApprox(hal::Vec3(140, 130, 80), 1e-9));
  const std::pair<const char*, const char*> refusals[] = {
      {"ArcTo 4 CW X150 I10",
       "Err 105 segment 4: arc end is not on the circle: its radius differs from the start's by 10.000000 (accepted: up "
       "to 0.010000)"},
      {"ArcTo 4 CCW X160 Z85 I10 N 0 0 1",
       "Err 105 segment 4: arc end is 5.000000 off the plane through the start (accepted: up to 0.010000; a planar arc "
       "has no helix)"},
      {"ArcTo 4 CW Z110 K5",
       "Err 105 ArcTo 4: K alone names no plane; give I K (ZX plane) or J K (YZ plane), with I0 or J0 if need be, or N "
       "i j k"},
      {"ArcTo 4 CW X160 I10 P2.5",
       "Err 105 ArcTo 4: P is the number of turns, a whole number from 1 (the arc alone) to 1000, got 2.5"},
      {"ArcTo 4 CW X160 I10 N 0 0",
       "Err 101 ArcTo takes N alone followed by three numbers (N i j k), got 'N'; usage: ArcTo id dir X.. Y.. Z.. I.. "
       "J.. K.. N i j k P.. F.."},
      {"ArcTo 5 CW X380 I120 K0", "Err 206 segment 5: axis Z leaves its travel at -40.000000"},
  };
  for (const auto& [line, reply] : refusals) {
    INFO(line);
    h.clear();
    h.send(line);
    CHECK(h.lines() == std::vector<std::string>{reply});
  }
}

namespace {
// Steps with a wall of material at x >= wall: crossing it latches the crossing point.
bool run_wall_until(QueueHarness& h, double wall, const std::string& line, double seconds) {
  for (long i = 0, n = static_cast<long>(seconds * 1000); i < n; ++i) {
    if (h.has(line)) return true;
    const hal::Vec3 before = h.rig.hw.where();
    h.step();
    const hal::Vec3 after = h.rig.hw.where();
    if (!h.rig.hw.tip && before.x() < wall && after.x() >= wall)
      h.rig.hw.touch_at(before + (wall - before.x()) / (after.x() - before.x()) * (after - before));
    else if (h.rig.hw.tip && after.x() < wall)
      h.rig.hw.tip = false;
  }
  return h.has(line);
}
}  // namespace

TEST_CASE("Probe through the Server: Hit with its id, Done — a MoveTo sent behind it starts where the Probe ended") {
  QueueHarness h;  // at (100, 100, 100); tip radius 2, RetractDist 0.5
  h.send("Probe 2 X150 F50\nMoveTo 3 Y120");
  CHECK(h.has("Ok Probe"));
  CHECK(h.has("Ok MoveTo"));
  REQUIRE(run_wall_until(h, 151, "Done 3", 30));
  auto hits = h.starting("Hit ");
  REQUIRE(hits.size() == 1);
  INFO(hits[0]);
  CHECK(hits[0].rfind("Hit 1 2 153.000", 0) == 0);  // the first hit of the journal, the Probe's id, the edge + r
  CHECK(h.has("MeasPt 153.000 100.000 100.000"));
  CHECK(h.starting("Done ") == std::vector<std::string>{"Done 2", "Done 3"});
  CHECK(h.starting("Failed").empty());
  h.step();
  // the MoveTo's unnamed axes kept the Probe's end: 0.5 back from the hit at x = 151
  CHECK(h.rig.position().isApprox(hal::Vec3(150.5, 120, 100), 1e-9));
}

TEST_CASE("Probe through the Server: a miss is Failed PartNotFound — what was sent behind it fails Stopped") {
  QueueHarness h;
  h.send("Probe 2 X150 F50\nMoveTo 3 Y120\nDwell 4 0.1");
  REQUIRE(run_wall_until(h, 1e9, "Failed 4 Stopped a stop dropped the queue", 30));
  CHECK(h.starting("Failed ") ==
        std::vector<std::string>{"Failed 2 PartNotFound no edge up to SearchDist past the target",
                                 "Failed 3 Stopped a stop dropped the queue", "Failed 4 Stopped a stop dropped the queue"});
  CHECK(h.starting("Done ").empty());
  CHECK(h.starting("Hit ").empty());
  h.step();
  CHECK(h.rig.position().isApprox(hal::Vec3(160, 100, 100), 1e-9));  // SearchDist beyond the target
}

TEST_CASE("Probe through the Server: refused when the search would leave the travel or has no direction — a held move is checked") {
  QueueHarness h;
  h.send("Probe 6 X495");
  CHECK(h.has("Err 206 segment 6: axis X leaves its travel at 505.000000"));
  h.send("Probe 7 X100 Y100 Z100");
  CHECK(h.starting("Err 105 segment 7: probe target must lie").size() == 1);
  h.send("Probe 8 X150\nMoveTo 9 Y900");
  CHECK(h.has("Err 206 segment 9: axis Y leaves its travel at 900.000000"));
  h.send("ArcTo 10 CW X200 Y200 I50");  // held: its circle depends on where the Probe ends
  CHECK(h.has("Ok ArcTo"));
  REQUIRE(run_wall_until(h, 151, "Done 8", 30));
  h.run(0.1);
  // from (150.5, 100) the centre is (200.5, 100): the end (200, 200) is not on that circle
  CHECK(h.starting("Failed") == std::vector<std::string>{"Failed 10 Refused not plannable from where the Probe ended"});
}

TEST_CASE("Probe through the Server: StopMv mid-probe fails the Probe and what waited behind it, Stopped") {
  QueueHarness h;
  h.send("Probe 2 X150 F50\nMoveTo 3 Y120");
  h.run(0.5);
  h.send("StopMv");
  REQUIRE(run_wall_until(h, 1e9, "Failed 3 Stopped a stop dropped the queue", 5));
  CHECK(h.starting("Failed ") == std::vector<std::string>{"Failed 2 Stopped a stop dropped the queue",
                                                          "Failed 3 Stopped a stop dropped the queue"});
  CHECK(h.starting("Done ").empty());
}
