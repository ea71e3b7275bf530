// The live measurement of an inspection plan over messd's protocol (MachineLink: one command
// at a time, MoveTo / Probe / ScanCirc / ScanLine each waited for until its Done, Hit and Scan
// lines collected by id).
#include "inspect_session.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Geometry>

namespace imess::messcap {
namespace {

using Eigen::Vector3d;
using metrology::Frame;
using metrology::InspectionPlan;
using metrology::PlanFeature;

class Session {
 public:
  Session(const InspectionPlan& plan, const LiveOptions& options, std::ostream& log)
      : plan_(plan), options_(options), log_(log), frame_(plan.placement), link_(options.endpoint) {}

  std::vector<metrology::MeasuredPoint> run() {
    link_.request("Hello messcap-inspect");
    link_.request("Take");
    if (plan_.probing.tip_radius) link_.request("Set TipRadius " + std::to_string(*plan_.probing.tip_radius));
    if (plan_.probing.search) link_.request("Set SearchDist " + std::to_string(*plan_.probing.search));
    tip_radius_ = plan_.probing.tip_radius ? *plan_.probing.tip_radius : link_.status_number("TipRadius");
    feed_ = options_.feed.value_or(plan_.probing.feed);
    if (has_scans()) {  // put back when the plan is done: a scan's step is the plan's, not the machine's
      machine_scan_step_ = scan_step_ = link_.get_number("ScanStep");
      machine_scan_speed_ = link_.get_number("ScanSpeed");
    }
    log_ << "messcap: measuring " << plan_.part << " on " << options_.endpoint.to_string() << " (tip radius "
         << tip_radius_ << " mm, feed " << feed_ << " mm/s)\n";

    // Up to the safe height where the machine stands, before anything moves sideways.
    move_z(frame_.point_to_parent(Vector3d(0, 0, plan_.probing.safe_z)).z());
    const auto order = measuring_order(plan_);
    try {
      for (std::size_t k = 0; k < order.size(); ++k) {
        measure_feature(*order[k]);
        if (plan_.alignment && k == 2) align();
      }
    } catch (...) {
      put_back_scan_step();
      throw;
    }
    if (has_scans()) set_scan_step(machine_scan_step_);
    release();
    return points_;
  }

 private:
  bool has_scans() const {
    return std::any_of(plan_.features.begin(), plan_.features.end(), [](const PlanFeature& f) { return !f.scans.empty(); });
  }

  // --- moves ---
  std::string feed_word() const {
    char buf[32];
    std::snprintf(buf, sizeof buf, " F%.1f", feed_);
    return buf;
  }
  void move_z(double z) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "Z%.4f", z);
    link_.queued("MoveTo", buf + feed_word());
  }
  void move_to(const Vector3d& part) { link_.queued("MoveTo", xyz_words(frame_.point_to_parent(part)) + feed_word()); }
  Vector3d above(const Vector3d& part) const { return {part.x(), part.y(), plan_.probing.safe_z}; }

  // Ball-centre positions of one probe point: the start (clearance off the surface) and the
  // target (touching the nominal surface), part coordinates.
  Vector3d start_of(const metrology::ProbeTarget& t) const {
    return t.point - (tip_radius_ + plan_.probing.clearance) * t.approach;
  }
  Vector3d target_of(const metrology::ProbeTarget& t) const { return t.point - tip_radius_ * t.approach; }

  void measure_feature(const PlanFeature& f) {
    if (f.probes.empty() && f.scans.empty())
      throw MachineError("feature '" + f.name + "' has no probe points or scans to measure");
    const std::size_t before = points_.size();
    for (std::size_t i = 0; i < f.probes.size(); ++i) {
      const Vector3d start = start_of(f.probes[i]);
      if (i == 0 || f.lift_between) {
        move_to(above(start));
        move_to(start);
      } else {
        move_to(start);
      }
      probe(f, f.probes[i]);
      move_to(start);
      if (f.lift_between || i + 1 == f.probes.size()) move_to(above(start));
    }
    for (const auto& s : f.scans) scan(f, s);
    const std::size_t n = points_.size() - before;
    log_ << "messcap: " << f.name << ": " << n << (n == 1 ? " point" : " points");
    if (!f.scans.empty()) log_ << " (" << f.scans.size() << (f.scans.size() == 1 ? " scan)" : " scans)");
    log_ << "\n";
  }

  // One scan: over its start at the safe height, down to the clearance off the surface there,
  // the scan (ScanCirc or ScanLine, its points collected), out to the clearance where it ends
  // and up. The points are surface points with the measured direction toward the surface and
  // the tip radius, as a Hit's are: fitted probe-compensated like hits.
  void scan(const PlanFeature& f, const metrology::ScanPath& s) {
    const double off = tip_radius_ + plan_.probing.clearance;
    const Vector3d start = s.start + off * s.normal_at_start();
    const Vector3d end = s.end_point() + off * s.normal_at_end();
    move_to(above(start));
    move_to(start);
    set_scan_step(s.step.value_or(machine_scan_step_));
    const metrology::Frame& m = frame_;
    const Eigen::Matrix3d& rot = m.rotation();
    std::string verb, words;
    char buf[256];
    if (s.kind == metrology::ScanPath::Kind::Circle) {
      const Vector3d c = m.point_to_parent(s.center), p = m.point_to_parent(s.start), a = rot * s.axis;
      std::snprintf(buf, sizeof buf, "%.4f %.4f %.4f %.4f %.4f %.4f %.9f %.9f %.9f %.4f %s", c.x(), c.y(), c.z(), p.x(), p.y(),
                    p.z(), a.x(), a.y(), a.z(), s.sweep_deg, s.bore ? "bore" : "boss");
      verb = "ScanCirc";
    } else {
      const Vector3d p = m.point_to_parent(s.start), q = m.point_to_parent(s.end), n = rot * s.normal;
      std::snprintf(buf, sizeof buf, "%.4f %.4f %.4f %.4f %.4f %.4f %.9f %.9f %.9f", p.x(), p.y(), p.z(), q.x(), q.y(), q.z(),
                    n.x(), n.y(), n.z());
      verb = "ScanLine";
    }
    words = buf;
    if (s.speed) {
      std::snprintf(buf, sizeof buf, " %.4f", *s.speed);
      words += buf;
    }
    // Time for the path at its speed (the machine's when the plan names none), plus the moves.
    const double speed = s.speed.value_or(machine_scan_speed_);
    const auto timeout = std::chrono::seconds{120 + static_cast<long>(2 * s.length() / std::max(speed, 0.1))};
    std::vector<protocol::HitMsg> taken;
    try {
      taken = link_.scan(verb, words, timeout);
    } catch (const MoveFailed& e) {
      if (e.reason() == "NoMeasuringProbe")
        throw MachineError("feature '" + f.name + "': " + e.what() +
                           ": a scan needs a measuring (analog) probe; measure the feature with probe points instead");
      throw MachineError("feature '" + f.name + "': " + e.what());
    } catch (const MachineError& e) {
      throw MachineError("feature '" + f.name + "': " + e.what());
    }
    for (const auto& h : taken) {
      metrology::MeasuredPoint p;
      p.feature = f.name;
      p.point = {h.p.x, h.p.y, h.p.z};
      const Vector3d dir(h.dir.x, h.dir.y, h.dir.z);
      if (dir.norm() > 0) {  // always, from messd; without one the point is taken as it is
        p.approach = dir.normalized();
        p.radius = h.radius;
      }
      points_.push_back(p);
    }
    move_to(end);
    move_to(above(end));
  }

  // After a failure, as far as messd still listens: its ScanStep as it was.
  void put_back_scan_step() noexcept {
    try {
      if (has_scans()) set_scan_step(machine_scan_step_);
    } catch (const std::exception&) {
    }
  }

  // Sends Set ScanStep when it differs from what messd has now.
  void set_scan_step(double step) {
    if (std::abs(step - scan_step_) < 1e-9) return;
    link_.request("Set ScanStep " + std::to_string(step));
    scan_step_ = step;
  }

  void probe(const PlanFeature& f, const metrology::ProbeTarget& t) {
    protocol::HitMsg h;
    try {
      h = link_.probe(xyz_words(frame_.point_to_parent(target_of(t))) + feed_word());
    } catch (const MachineError& e) {
      throw MachineError("feature '" + f.name + "': " + e.what());
    }
    metrology::MeasuredPoint p;
    p.feature = f.name;
    p.point = {h.p.x, h.p.y, h.p.z};
    const Vector3d dir(h.dir.x, h.dir.y, h.dir.z);
    if (dir.norm() > 0) {
      p.approach = dir.normalized();
      p.radius = h.radius;
    }
    points_.push_back(p);
  }

  // The part frame from the alignment features measured so far: the rest is probed in it.
  void align() {
    frame_ = metrology::align_part(plan_, points_);
    const Vector3d o = frame_.translation();
    const double turn = std::atan2(frame_.rotation()(1, 0), frame_.rotation()(0, 0)) * 180 / M_PI;
    char buf[160];
    std::snprintf(buf, sizeof buf, "messcap: part frame from %s, %s, %s: origin %.4f %.4f %.4f, x axis turned %.4f deg about z\n",
                  plan_.alignment->primary.c_str(), plan_.alignment->secondary.c_str(), plan_.alignment->tertiary.c_str(),
                  o.x(), o.y(), o.z(), turn);
    log_ << buf;
  }

  // Tells messd the part frame (a messd with part frames keeps it for other clients; an older
  // one answers Err, which is only noted), then gives up control.
  void release() {
    if (plan_.alignment) {
      const Vector3d o = frame_.translation(), x = frame_.rotation().col(0), z = frame_.rotation().col(2);
      char buf[256];
      std::snprintf(buf, sizeof buf, "SetFrame %s O %.6f %.6f %.6f X %.9f %.9f %.9f Z %.9f %.9f %.9f", plan_.part.c_str(), o.x(),
                    o.y(), o.z(), x.x(), x.y(), x.z(), z.x(), z.y(), z.z());
      const std::string reply = link_.try_request(buf);
      if (reply.rfind("Err ", 0) == 0) log_ << "messcap: messd keeps no part frames (" << reply << "); the frame is in the report\n";
    }
    link_.request("Release");
    link_.finish();
  }

  const InspectionPlan& plan_;
  const LiveOptions& options_;
  std::ostream& log_;
  Frame frame_;
  MachineLink link_;
  double tip_radius_ = 0, feed_ = 0;
  double machine_scan_step_ = 0, scan_step_ = 0, machine_scan_speed_ = 0;  // messd's ScanStep, ScanSpeed
  std::vector<metrology::MeasuredPoint> points_;
};

}  // namespace

std::vector<const PlanFeature*> measuring_order(const InspectionPlan& plan) {
  std::vector<const PlanFeature*> order;
  if (plan.alignment)
    for (const auto* name : {&plan.alignment->primary, &plan.alignment->secondary, &plan.alignment->tertiary})
      order.push_back(&plan.feature(*name));
  for (const auto& f : plan.features)
    if (std::find(order.begin(), order.end(), &f) == order.end()) order.push_back(&f);
  return order;
}

std::vector<metrology::MeasuredPoint> measure_live(const InspectionPlan& plan, const LiveOptions& options, std::ostream& log) {
  return Session(plan, options, log).run();
}

void announce_result(const InspectionPlan& plan, const metrology::InspectionResult& result, const LiveOptions& options,
                     std::ostream& log) {
  const std::size_t open = result.out_of_tolerance() + result.not_evaluated();
  std::string part = plan.part;
  for (char& c : part)
    if (c == ' ' || c == '\t') c = '_';  // one word on the wire
  const std::string line = "Verdict " + part + " " + std::to_string(result.characteristics.size() - open) + " " +
                           std::to_string(open) + (open == 0 ? " pass" : " fail");
  MachineLink link(options.endpoint);
  link.try_request("Hello messcap-inspect");
  const std::string reply = link.try_request(line);
  if (reply.rfind("Err ", 0) == 0) log << "messcap: messd did not take the result (" << reply << ")\n";
  link.finish();
}

}  // namespace imess::messcap
