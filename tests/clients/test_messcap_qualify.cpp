// messcap qualify without a machine: the touch plan, the qualification computed from synthetic
// hits (a known ball radius, sphere position and form), the refusals, the messdrc edit, and the
// built program against a fake daemon that plays a sphere (a bumpy one, or none).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "child_process.hpp"
#include "fake_daemon.hpp"
#include "messdrc_edit.hpp"
#include "qualification.hpp"

using namespace imess::messcap;
using Eigen::Vector3d;
using imess::test::client_binary;
using imess::test::FakeDaemon;
using imess::test::FakeDaemonScript;
using imess::test::read_file;
using imess::test::run_program;
using imess::test::TempDir;

namespace {

const ReferenceSphere kSphere{{750, 650, 60}, 25};

// The hits messd would report for the touches of `plan` on a sphere whose true centre is
// `actual`, touched by a ball of radius `ball`, compensated with `compensate` (TipRadius) and
// shifted by the probe offset `offset`; bump[k] moves touch k's ball centre outward.
std::vector<imess::metrology::ProbedPoint> hits_on(const TouchPlan& plan, const Vector3d& actual, double ball,
                                                   double compensate, const Vector3d& offset,
                                                   const std::vector<double>& bump = {}) {
  std::vector<imess::metrology::ProbedPoint> hits;
  for (std::size_t k = 0; k < plan.touches.size(); ++k) {
    const Vector3d d = plan.touches[k].approach;  // messd's direction: the motion's
    const Vector3d outward = (plan.touches[k].target - actual).normalized();
    const double extra = k < bump.size() ? bump[k] : 0.0;
    const Vector3d centre = actual + (kSphere.radius() + ball + extra) * outward + offset;
    hits.push_back({centre + compensate * d, d, compensate});
  }
  return hits;
}

}  // namespace

TEST_CASE("qualify: the touch plan is a ring 10 degrees above the equator and the pole, approached toward the centre") {
  const TouchPlan plan = plan_touches(kSphere, 2.0);
  REQUIRE(plan.touches.size() == 9);
  for (std::size_t k = 0; k < plan.touches.size(); ++k) {
    const Touch& t = plan.touches[k];
    INFO("touch " << k);
    CHECK((t.target - kSphere.centre).norm() == Approx(14.5));
    CHECK((t.start - kSphere.centre).norm() == Approx(19.5));
    CHECK(t.approach.norm() == Approx(1.0));
    CHECK((t.approach + (t.target - kSphere.centre).normalized()).norm() < 1e-12);
    const double elevation = std::asin((t.target - kSphere.centre).normalized().z()) * 180 / M_PI;
    CHECK(elevation == Approx(k + 1 < plan.touches.size() ? 10.0 : 90.0));
    CHECK(plan.safe_z > t.start.z());
  }
  // Evenly round the ring: neighbours 45 degrees apart.
  const Vector3d a = plan.touches[0].target - kSphere.centre, b = plan.touches[1].target - kSphere.centre;
  CHECK(std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x()) == Approx(M_PI / 4));
  CHECK(plan.safe_z == Approx(60 + 14.5 + 20));
  CHECK(plan_touches(kSphere, 2.0, TouchPattern{5}).touches.size() == 6);
  CHECK_THROWS_WITH(plan_touches(kSphere, 2.0, TouchPattern{2}), Catch::Contains("3 to 72 points"));
}

TEST_CASE("qualify: the radius, offset and form come from the ball centres, whatever TipRadius compensated them") {
  const TouchPlan plan = plan_touches(kSphere, 1.9);
  const Vector3d actual = kSphere.centre + Vector3d(0.012, -0.007, 0.003);  // the sphere is not quite at its nominal
  const Vector3d previous(0.25, 0, -0.1);
  const auto hits = hits_on(plan, actual, 2.0034, 1.9, previous);
  const Qualification q = qualify_probe(kSphere, hits, previous);
  CHECK(q.tip_radius == Approx(2.0034).margin(1e-9));
  CHECK((q.centre_fit.center - (actual + previous)).norm() < 1e-9);
  CHECK((q.shift - (kSphere.centre - actual - previous)).norm() < 1e-9);
  CHECK((q.offset - (kSphere.centre - actual)).norm() < 1e-9);  // previous + nominal - fitted
  CHECK(q.form < 1e-9);
  CHECK(q.residuals.size() == 9);
  CHECK_FALSE(refusal(q, {}));
}

TEST_CASE("qualify: the form error is the range of the centres' residuals, and above the limit it refuses") {
  const TouchPlan plan = plan_touches(kSphere, 2.0);
  const auto hits = hits_on(plan, kSphere.centre, 2.0, 2.0, Vector3d::Zero(), {0.004, 0, 0, 0, -0.003});
  const Qualification q = qualify_probe(kSphere, hits, Vector3d::Zero());
  double lo = 1e9, hi = -1e9;
  for (const auto& h : hits) {  // residuals worked out here from the fitted sphere
    const double e = (h.centre() - q.centre_fit.center).norm() - q.centre_fit.radius();
    lo = std::min(lo, e);
    hi = std::max(hi, e);
  }
  CHECK(q.form == Approx(hi - lo).margin(1e-12));
  CHECK(q.form > 0.003);  // the two bumps 7 um apart, less what the fit takes up
  CHECK(q.form < 0.007);
  const auto why = refusal(q, QualificationLimits{0.003});
  REQUIRE(why);
  CHECK_THAT(*why, Catch::Contains("form error") && Catch::Contains("above the limit 0.0030 mm"));
  CHECK_FALSE(refusal(q, QualificationLimits{0.01}));
}

TEST_CASE("qualify: touches that cannot qualify, and values messd cannot hold, are refused with the reason") {
  const TouchPlan plan = plan_touches(kSphere, 2.0);
  auto hits = hits_on(plan, kSphere.centre, 2.0, 2.0, Vector3d::Zero());
  CHECK_THROWS_WITH(qualify_probe(kSphere, std::span(hits).first(3), Vector3d::Zero()), Catch::Contains("at least 4"));
  CHECK_THROWS_WITH(qualify_probe(ReferenceSphere{kSphere.centre, 30}, hits, Vector3d::Zero()),
                    Catch::Contains("not larger than the reference sphere") && Catch::Contains("--diameter"));
  auto forced = hits;
  forced[2].approach = Vector3d::Zero();
  CHECK_THROWS_WITH(qualify_probe(kSphere, forced, Vector3d::Zero()), Catch::Contains("touch 3 has no approach"));

  const Qualification far = qualify_probe(kSphere, hits, Vector3d(0, 99.99, 0) + Vector3d(0, 0.5, 0));
  REQUIRE(refusal(far, {}));
  CHECK_THAT(*refusal(far, {}), Catch::Contains("offset in Y 100.4900 mm"));
}

TEST_CASE("qualify: the messdrc gets the new values on its own lines, comments and other lines kept") {
  const std::vector<RcSetting> s = {{"TipRadius", "1.999998", "mm"}, {"ProbeOffX", "0.012000", "offset"},
                                    {"ProbeOffY", "-0.007000", ""}};
  const std::string rc =
      "# stylus 4 mm\nSpeedLevel 1.0      # speeds\nTipRadius 2.0       # mm: half the ball\nTipReversed false\n";
  CHECK(set_messdrc_values(rc, s, "rc") ==
        "# stylus 4 mm\nSpeedLevel 1.0      # speeds\nTipRadius 1.999998  # mm: half the ball\nTipReversed false\n"
        "ProbeOffX 0.012000  # offset\nProbeOffY -0.007000\n");
  // A second run replaces what the first appended; no newline at the end, a key without value.
  const std::string again = set_messdrc_values("ProbeOffY 1\nProbeOffX 2\nTipRadius", s, "rc");
  CHECK(again == "ProbeOffY -0.007000\nProbeOffX 0.012000\nTipRadius 1.999998\n");
  CHECK_THROWS_WITH(set_messdrc_values("TipRadius 2\n# x\nTipRadius 3\n", s, "stylus.rc"),
                    Catch::Contains("stylus.rc: line 3: TipRadius is set again (first on line 1)"));
}

namespace {

// A messd stand-in holding a reference sphere (none when `present` is false) touched by a 2 mm
// ball; bump[k] moves touch k's contact outward. Probe targets are answered with the hit where
// the ball meets the sphere on the line toward its centre.
FakeDaemonScript sphere_daemon(bool present, std::vector<double> bump) {
  auto touches = std::make_shared<int>(0);
  return {0, {"CurrCor 430.000 330.000 100.000"}, [=](const std::string& line) -> std::vector<std::string> {
            std::istringstream in(line);
            std::string verb, id;
            in >> verb >> id;
            if (verb == "Get") return {"Ok Get " + id + " 0.000"};
            if (verb == "Status")
              return {"Ok Status State idle Pos 430.000 330.000 100.000 Loops closed Tip free Limits none Homed no "
                      "Referenced no TipRadius 2.000 SpeedLevel 1.000 Clients 1 Control messcap@127.0.0.1"};
            if (verb == "MoveTo") return {"Ok MoveTo", "Done " + id};
            if (verb == "Probe") {
              if (!present) return {"Ok Probe", "Failed " + id + " PartNotFound no edge up to SearchDist past the target"};
              Vector3d target;
              for (int k = 0; k < 3; ++k) {
                std::string w;
                in >> w;
                target[k] = std::stod(w.substr(1));
              }
              const Vector3d outward = (target - kSphere.centre).normalized();
              const std::size_t k = static_cast<std::size_t>((*touches)++);
              const Vector3d centre = kSphere.centre + (14.5 + (k < bump.size() ? bump[k] : 0.0)) * outward;
              const Vector3d p = centre - 2.0 * outward;
              char hit[200];
              std::snprintf(hit, sizeof hit, "Hit %zu %s %.4f %.4f %.4f %.6f %.6f %.6f 2.0000 1.000000", k + 1, id.c_str(), p.x(),
                            p.y(), p.z(), -outward.x(), -outward.y(), -outward.z());
              return {"Ok Probe", hit, "Done " + id};
            }
            if (verb == "Qualify") return {"Ok Qualify", "Qualified TipRadius 2.000000 Offset 0 0 0 Form 0"};
            return {"Ok " + verb};
          }};
}

bool received_verb(const FakeDaemon& d, const std::string& verb) {
  for (const auto& l : d.received())
    if (l == verb || l.rfind(verb + " ", 0) == 0) return true;
  return false;
}

}  // namespace

TEST_CASE("messcap qualify: a sphere missing from where --sphere says is named, and nothing is qualified") {
  FakeDaemon daemon(sphere_daemon(false, {}));
  const auto r = run_program({client_binary("messcap"), "qualify", daemon.address(), "--sphere", "750,650,60", "--diameter", "25"});
  INFO(r.err);
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("touch 1 of 9 found no surface") &&
                        Catch::Contains("the sphere is not at 750.000,650.000,60.000 (diameter 25.0000 mm)"));
  CHECK_FALSE(received_verb(daemon, "Qualify"));
}

TEST_CASE("messcap qualify: a form error above --max-form is reported and refused, messd keeps its values") {
  FakeDaemon daemon(sphere_daemon(true, {0.008}));
  TempDir dir;
  const std::string rc = dir.file("stylus.rc");
  { std::ofstream(rc) << "TipRadius 2.0\n"; }
  const auto r = run_program({client_binary("messcap"), "qualify", daemon.address(), "--sphere", "750,650,60", "--diameter", "25",
                              "--rc", rc, "--json", dir.file("q.json")});
  INFO(r.out << r.err);
  CHECK(r.status == 5);
  CHECK_THAT(r.err, Catch::Contains("not qualified: the sphere's form error") && Catch::Contains("(--max-form)"));
  CHECK_THAT(r.out, Catch::Contains("touches       9"));
  CHECK_FALSE(received_verb(daemon, "Qualify"));
  CHECK(received_verb(daemon, "Release"));
  CHECK(read_file(rc) == "TipRadius 2.0\n");
  CHECK_THAT(read_file(dir.file("q.json")), Catch::Contains("\"qualified\": false"));

  // The same touches within a wider limit qualify.
  FakeDaemon second(sphere_daemon(true, {0.008}));
  const auto ok = run_program({client_binary("messcap"), "qualify", second.address(), "--sphere", "750,650,60", "--diameter", "25",
                               "--max-form", "0.01", "--rc", rc});
  INFO(ok.err);
  CHECK(ok.status == 0);
  CHECK(received_verb(second, "Qualify"));
  CHECK_THAT(read_file(rc), Catch::StartsWith("TipRadius 2.00") && Catch::Contains("ProbeOffZ "));
}

TEST_CASE("messcap qualify: bad arguments say what is accepted") {
  const std::string messcap = client_binary("messcap");
  auto r = run_program({messcap, "qualify", "--diameter", "25"});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("qualify needs --sphere X,Y,Z"));
  r = run_program({messcap, "qualify", "--sphere", "1,2,x", "--diameter", "25"});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("expected the nominal centre as X,Y,Z"));
  r = run_program({messcap, "qualify", "--sphere", "1,2,3", "--diameter", "-1"});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("calibrated diameter in mm, above 0"));
  r = run_program({messcap, "qualify", "--sphere", "1,2,3", "--diameter", "25", "--points", "2"});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("3 to 72"));
}
