// DirectCMM's offline test sequence (BRIEF §2) against a real messd on the simulated CMM:
// SearchDist 10, RetractDist 5, moves at 11 mm/s and Probes into the 1996 cube (left face at
// x = 400, y 300..400, z 0..80; the machine starts at (430, 330, 100)). All lines go in one
// burst: the moves after each Probe wait for its Done and start where it ended. A hit with
// the Probe's id on the face, a miss beside the cube (PartNotFound), and an unexpected hit
// of a plain move into the front face.
#include <catch2/catch.hpp>

#include <sstream>

#include "daemon_process.hpp"

using namespace imess::test;

namespace {
std::vector<double> numbers_after(const std::string& line, int skip) {
  std::istringstream in(line);
  std::string word;
  for (int i = 0; i < skip; ++i) in >> word;
  std::vector<double> out;
  double v;
  while (in >> v) out.push_back(v);
  return out;
}

bool seen(const LineClient& c, const std::string& line) {
  for (const auto& l : c.seen())
    if (l == line) return true;
  return false;
}
}  // namespace

static void offline_sequence(const std::string& config) {
  DaemonProcess messd({"--config", std::string(IMESS_SOURCE_DIR) + "/tests/e2e/" + config});
  LineClient c(messd.port());
  REQUIRE(c.request("Set SearchDist 10") == "Ok Set");
  REQUIRE(c.request("Set RetractDist 5") == "Ok Set");
  c.send("MoveTo 1 X380 Y350 Z100\n"
         "MoveTo 10 Z40 F11\n"
         "Probe 2 X395 F11\n"        // the left face at x = 400: a hit, then a retract to x = 393
         "MoveTo 3 Y250\n"           // from where the Probe ended
         "Probe 4 X398 F11\n"        // beside the cube: searched up to x = 408, nothing there
         "MoveTo 5 Y350 F11\n"       // at x = 408 straight into the front face (y = 300): unexpected
         "MoveTo 6 Z100");           // never runs
  REQUIRE(c.until([](const std::string& l) { return l.rfind("Failed 6", 0) == 0; }, 60));
  INFO(c.raw());
  // the hit: the Probe's id, on the face (yaw 0.3°: x = 400 + 0.00524·(y − 350) ... at y = 350, 400)
  std::vector<std::string> hits;
  for (const auto& l : c.seen())
    if (l.rfind("Hit ", 0) == 0) hits.push_back(l);
  REQUIRE(hits.size() == 1);
  const auto h = numbers_after(hits[0], 1);  // seq id x y z i j k r t
  REQUIRE(h.size() == 10);
  CHECK(h[1] == 2);
  CHECK(h[2] == Approx(400.0).margin(0.005));
  CHECK(h[3] == Approx(350.0).margin(1e-3));
  CHECK(h[4] == Approx(40.0).margin(1e-3));
  CHECK(h[5] == Approx(1.0).margin(1e-6));
  CHECK(seen(c, "Done 1"));
  CHECK(seen(c, "Done 10"));
  CHECK(seen(c, "Done 2"));
  CHECK(seen(c, "Done 3"));
  CHECK(seen(c, "Failed 4 PartNotFound no edge up to SearchDist past the target"));
  CHECK(seen(c, "Failed 5 Stopped a stop dropped the queue"));  // behind a failed Probe: never planned
  CHECK(seen(c, "Failed 6 Stopped a stop dropped the queue"));

  // The unexpected hit: a plain move into the front face, from where the miss ended.
  c.send("MoveTo 7 Y350 F11");
  REQUIRE(c.until([](const std::string& l) { return l.rfind("Failed 7", 0) == 0; }, 30));
  CHECK(seen(c, "Failed 7 UnexpectedHit probe touched: stopped, retracted, no point"));
  hits.clear();
  for (const auto& l : c.seen())
    if (l.rfind("Hit ", 0) == 0) hits.push_back(l);
  CHECK(hits.size() == 1);  // no point from it
  c.send("Quit");
}

TEST_CASE("DirectCMM offline sequence on the simulated 3D-Step machine: hit, miss (PartNotFound), unexpected hit", "[long]") {
  offline_sequence("backend-parport-3dstep.json");
}
