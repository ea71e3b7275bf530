// The 1996 cube's bore measured over I++ DME, as inspection software does it: eight PtMeas
// with IJK around the bore of config/sim-servo-card.json, replayed against messd's parts in
// virtual time (golden_harness). The reported points fit the bore within 1 µm, each is the
// point the MESSD clients receive as Hit, and the IJK is the wall's normal.
#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "golden_harness.hpp"
#include "imess/metrology/fit.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::golden {
namespace {

struct Measured {
  std::vector<Eigen::Vector3d> points, normals;  // from the I++ session's `#` lines
  std::vector<Eigen::Vector3d> hits;             // from the MESSD client's Hit lines
  std::vector<std::string> closing;              // the session's lines after the last PtMeas
};

// "00004 # X(475.0000), Y(350.0000), Z(40.0000), IJK(-1.000000, 0.000000, 0.000000)"
bool read_report(const std::string& line, Eigen::Vector3d& p, Eigen::Vector3d& n) {
  return std::sscanf(line.c_str(), "%*5s # X(%lf), Y(%lf), Z(%lf), IJK(%lf, %lf, %lf)", &p.x(), &p.y(), &p.z(), &n.x(),
                     &n.y(), &n.z()) == 6;
}

// Eight points around the bore (centre X460 Y350, Ø30) at half height, the nominal 0.2 mm
// off the real wall, so the point must come from the touch and not from the nominal.
Measured measure_bore(double nominal_radius) {
  std::ostringstream script;
  script << "@ config/sim-servo-card.json\n+2 ipp\n2> 00001 StartSession()\n"
         << "2> 00002 OnPtMeasReport(X(), Y(), Z(), IJK())\n"
         << "2> 00003 GoTo(X(460), Y(350), Z(100))\n= 2000 ms\n2> 00004 GoTo(Z(40))\n= 2000 ms\n";
  for (int k = 0; k < 8; ++k) {
    const double a = k * std::numbers::pi / 4 + 0.1;
    char line[200];
    std::snprintf(line, sizeof line, "2> %05d PtMeas(X(%.4f), Y(%.4f), Z(40), IJK(%.6f, %.6f, 0))\n= 4000 ms\n", 5 + k,
                  460 + nominal_radius * std::cos(a), 350 + nominal_radius * std::sin(a), -std::cos(a), -std::sin(a));
    script << line;
  }
  script << "2> 00013 GoTo(Z(100))\n= 2000 ms\n2> 00014 EndSession()\n";
  const auto out = replay(parse_transcript(script.str(), "bore"), "bore");
  Measured m;
  for (const auto& e : out) {
    if (e.kind != EntryKind::Receive) continue;
    Eigen::Vector3d p, n;
    if (e.client == 2 && read_report(e.text, p, n)) {
      m.points.push_back(p);
      m.normals.push_back(n);
    } else if (e.client == 2 && (e.text.rfind("00013", 0) == 0 || e.text.rfind("00014", 0) == 0)) {
      m.closing.push_back(e.text);
    } else if (e.client == 1) {
      const auto msg = protocol::parse_message(e.text);
      if (const auto* hit = std::get_if<protocol::HitMsg>(&msg)) m.hits.emplace_back(hit->p.x, hit->p.y, hit->p.z);
    }
  }
  return m;
}

TEST_CASE("I++ DME: eight PtMeas with IJK on the 1996 cube's bore fit Ø30 within 1 µm, each point is the MESSD Hit") {
  const Measured m = measure_bore(15.2);
  REQUIRE(m.points.size() == 8);
  REQUIRE(m.hits.size() == 8);
  std::vector<Eigen::Vector2d> xy;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const auto& p = m.points[i];
    CHECK(p.z() == Approx(40).margin(1e-3));
    CHECK((p - m.hits[i]).norm() < 1e-4);  // the same point, written to 4 decimals
    // The wall's normal points from the wall to the bore's axis.
    const Eigen::Vector3d inward = Eigen::Vector3d(460 - p.x(), 350 - p.y(), 0).normalized();
    CHECK(m.normals[i].dot(inward) > 0.9999);
    xy.emplace_back(p.x(), p.y());
  }
  const auto fit = metrology::fit_circle2d(xy);
  REQUIRE(fit.ok());
  const auto& c = fit.value();
  INFO("centre " << c.center.transpose() << " diameter " << c.diameter << " form " << c.stats.form());
  CHECK(std::abs(c.diameter - 30) <= 0.001);
  CHECK(std::abs(c.center.x() - 460) <= 0.001);
  CHECK(std::abs(c.center.y() - 350) <= 0.001);
  // Out of the bore, and the session ended.
  CHECK(m.closing == std::vector<std::string>{"00013 &", "00013 %", "00014 &", "00014 %"});
}

}  // namespace
}  // namespace imess::golden
