// The I++ DME motion steps on the Server's planner and segment ring: GoTo (one line at the
// tool's GoToPar.Speed), PtMeas (to the approach point, the search along −IJK at
// PtMeasPar.Speed through the same probe cycle as MESSD's Probe, the retract), Home; the
// loop's events that finish them; measured points, KeyPress and the move report daemon.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "imess/net/ipp_server.hpp"
#include "imess/net/wording.hpp"
#include "imess/planner/probe.hpp"

namespace imess::net {

using ippdme::ErrorCode;
using ippdme::Item;
using ippdme::Param;
using ippdme::Point3;
using ippdme::Value;

namespace {
constexpr int kCoordinateDecimals = 4;  // mm
constexpr int kVectorDecimals = 6;
constexpr double kMinReportPeriod = 0.1;  // s: at most 10 move reports a second

double norm(const Point3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// v / |v|, scaled by its largest component first so that neither IJK(1e200, 1e200, 1e200) nor
// IJK(1e-200, 0, 0) over- or underflows; nullopt when v has no direction (zero, not finite).
std::optional<Point3> unit(Point3 v) {
  const double m = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  if (!(m > 0) || !std::isfinite(m)) return std::nullopt;
  for (double& c : v) c /= m;
  const double len = norm(v);
  for (double& c : v) c /= len;
  return v;
}

bool finite(const Point3& p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// Why a segment failed, as the spec numbers it (docs/ippdme.md, "Errors the server sends").
ErrorCode error_of(core::FailReason why) {
  switch (why) {
    case core::FailReason::Stopped:
    case core::FailReason::HostStall: return ErrorCode::TransactionAborted;
    case core::FailReason::OutOfTravel:
    case core::FailReason::IntoLimit: return ErrorCode::MachineLimitEncountered;
    case core::FailReason::Faulted: return ErrorCode::MachineInErrorState;
    case core::FailReason::UnexpectedHit:
    case core::FailReason::TipTouched: return ErrorCode::IllegalTouch;
    case core::FailReason::PartNotFound:
    case core::FailReason::ScanLostContact: return ErrorCode::SurfaceNotFound;
    case core::FailReason::ScanOverRange: return ErrorCode::IllegalTouch;
    case core::FailReason::NoMeasuringProbe: return ErrorCode::ToolNotCalibrated;
    case core::FailReason::ProbeOff: return ErrorCode::ToolNotCalibrated;
    case core::FailReason::OffPath:
    case core::FailReason::Refused: return ErrorCode::ErrorProcessingMethod;
  }
  return ErrorCode::ErrorProcessingMethod;
}
}  // namespace

std::uint32_t IppServer::next_id() {
  if (next_id_ >= kClientId - 8) next_id_ = kIdBase;
  return next_id_++;
}

Point3 IppServer::tip_machine() const {
  const hal::Vec3 p = gateway_.layout().cartesian(gateway_.snapshot().position);
  return {p.x(), p.y(), p.z()};
}

Point3 IppServer::tip_here() const { return csy_.from_machine(tip_machine()); }

planner::Pose IppServer::pose_at(const Point3& xyz) const {
  planner::Pose pose = rest_ ? *rest_ : gateway_.pose_of(gateway_.snapshot().position);
  for (int c = 0; c < 3; ++c) pose[gateway_.layout().cartesian_axis(c)] = xyz[c];
  return pose;
}

// The lines planned from where the last step left the machine, all or none (a dry run
// first), flushed to end at rest and fed to the loop.
IppServer::Planned IppServer::plan_lines(std::vector<planner::Line> lines, std::string& why) {
  return plan_requests(std::vector<planner::Request>(lines.begin(), lines.end()), why);
}

IppServer::Planned IppServer::plan_requests(const std::vector<planner::Request>& lines, std::string& why) {
  MotionGateway& s = gateway_;
  if (!s.planning()) {
    const auto& snap = s.snapshot();
    if ((snap.mode != core::Mode::Idle && snap.mode != core::Mode::Free) || s.loop_holds_segments()) {
      why = std::string("the machine is busy (State ") + std::string(mode_name(snap.mode)) + ")";
      // Braking, retracting: the step waits for rest; a fault does not pass by itself.
      return snap.mode == core::Mode::Fault ? Planned::Refused : Planned::Busy;
    }
    s.start_at(rest_ ? *rest_ : s.pose_of(snap.position));
  }
  planner::Planner dry(s.machine(), s.options());
  dry.set_position(s.planned_end());
  for (const auto& l : lines)
    if (auto r = dry.append(l); !r.ok()) {
      why = planner::describe(r, s.machine());
      return r.error == planner::PlanError::OutOfTravel ? Planned::OutOfTravel : Planned::Refused;
    }
  for (const auto& l : lines) s.append(l);  // the same id once (a probe's approach and search)
  s.flush_and_feed();
  return Planned::Yes;
}

ErrorCode IppServer::refusal_error(Planned p) {
  return p == Planned::OutOfTravel ? ErrorCode::MachineLimitEncountered : ErrorCode::ErrorProcessingMethod;
}

// A move needs the machine: the session takes control back (the user is no longer enabled);
// false (answered 0511) when someone else holds it.
bool IppServer::take_machine(const Pending& p) {
  std::string why;
  if (!claim_control(false, why)) {
    spdlog::warn("I++ DME: {}: {}", ippdme::method_name(p.command), why);
    fail(p.tag, ErrorCode::ErrorProcessingMethod, ippdme::method_name(p.command));
    return false;
  }
  if (machine_faulted()) {  // ClearAllErrors resets it once its cause is gone
    fail(p.tag, ErrorCode::MachineInErrorState, ippdme::method_name(p.command));
    return false;
  }
  user_enabled_ = false;
  return true;
}

bool IppServer::start_goto(const Pending& p, const ippdme::GoTo& c) {
  const std::string_view name = ippdme::method_name(p.command);
  std::string why;
  if (c.target.tool_a || c.target.tool_b || c.target.tool_c) {
    fail(p.tag, ErrorCode::ArgumentNotSupported, name);  // no probe head with angles here
    return true;
  }
  if (!take_machine(p)) return true;
  Point3 t = tip_here();
  if (c.target.x) t[0] = *c.target.x;
  if (c.target.y) t[1] = *c.target.y;
  if (c.target.z) t[2] = *c.target.z;
  const Point3 target = csy_.to_machine(t);
  if (!finite(target)) {  // beyond every limit in machine coordinates: the spec's out-of-range error
    fail(p.tag, ErrorCode::MachineLimitEncountered, name);
    return true;
  }
  const planner::Line line{next_id(), pose_at(target), tools_.act(Param::GoToSpeed), planner::ProbePhase::None,
                           tools_.lowered(Param::GoToAccel)};
  if (const auto planned = plan_lines({line}, why); planned != Planned::Yes) {
    if (planned == Planned::Busy) return wait_for_rest();
    spdlog::info("I++ DME: GoTo refused: {}", why);
    fail(p.tag, refusal_error(planned), name);
    return true;
  }
  step_ = Step::GoTo;
  first_id_ = wait_id_ = line.id;
  return false;
}

bool IppServer::start_ptmeas(const Pending& p, const ippdme::PtMeas& c) {
  const std::string_view name = ippdme::method_name(p.command);
  std::string why;
  if (!tools_.active() || !tools_.active()->measures) {
    fail(p.tag, ErrorCode::ToolNotDefined, name);  // UnDefTool or NoTool: nothing measures
    return true;
  }
  if (c.nominal.tool_a || c.nominal.tool_b || c.nominal.tool_c) {
    fail(p.tag, ErrorCode::ArgumentNotSupported, name);
    return true;
  }
  if (!take_machine(p)) return true;
  const Point3 here = tip_here();
  Point3 nominal = here;
  if (c.nominal.x) nominal[0] = *c.nominal.x;
  if (c.nominal.y) nominal[1] = *c.nominal.y;
  if (c.nominal.z) nominal[2] = *c.nominal.z;
  // The surface normal: IJK, else from the nominal towards where the tip stands (§9).
  const Point3 toward = c.ijk ? Point3{c.ijk->i, c.ijk->j, c.ijk->k}
                              : Point3{here[0] - nominal[0], here[1] - nominal[1], here[2] - nominal[2]};
  const auto direction = unit(toward);
  if (!direction || (!c.ijk && norm(toward) < 1e-6)) {  // without IJK: the tip must stand off the nominal
    fail(p.tag, ErrorCode::VectorHasNoNorm, name);
    return true;
  }
  const Point3 n = *direction;
  // The nominal is a point of the surface: the ball's centre touches it at nominal + n·r;
  // the approach point and the search's end lie Approach before and Search beyond that.
  const double approach = tools_.act(Param::Approach), r = tools_.active()->radius;
  auto along = [&](double d) { return Point3{nominal[0] + n[0] * d, nominal[1] + n[1] * d, nominal[2] + n[2] * d}; };
  approach_m_ = csy_.to_machine(along(r + approach));
  normal_m_ = csy_.vector_to_machine(n);
  const Point3 nominal_m = csy_.to_machine(along(r));
  if (!finite(approach_m_) || !finite(nominal_m)) {
    fail(p.tag, ErrorCode::MachineLimitEncountered, name);
    return true;
  }
  const double feed = tools_.act(Param::GoToSpeed);
  std::vector<planner::Line> lines;
  const Point3 at = tip_machine();
  const std::uint32_t first = next_id(), probe = next_id();
  if (norm({approach_m_[0] - at[0], approach_m_[1] - at[1], approach_m_[2] - at[2]}) > 1e-4)
    lines.push_back({first, pose_at(approach_m_), feed, planner::ProbePhase::None});
  const auto cycle = planner::probe_cycle(probe, pose_at(approach_m_), pose_at(nominal_m),
                                          {approach, tools_.act(Param::Search), feed, tools_.act(Param::PtMeasSpeed)});
  if (!cycle) {
    fail(p.tag, ErrorCode::VectorHasNoNorm, name);
    return true;
  }
  if (cycle->approach) lines.push_back(*cycle->approach);
  lines.push_back(cycle->search);
  for (auto& l : lines)  // GoToPar.Accel / PtMeasPar.Accel when the client lowered them
    l.max_accel = tools_.lowered(l.probe == planner::ProbePhase::Search ? Param::PtMeasAccel : Param::GoToAccel);
  if (const auto planned = plan_lines(std::move(lines), why); planned != Planned::Yes) {
    if (planned == Planned::Busy) return wait_for_rest();
    spdlog::info("I++ DME: PtMeas refused: {}", why);
    fail(p.tag, refusal_error(planned), name);
    return true;
  }
  step_ = Step::PtMeas;
  first_id_ = first;
  wait_id_ = probe;
  hit_seen_ = false;
  return false;
}

bool IppServer::machine_faulted() const { return gateway_.snapshot().mode == core::Mode::Fault; }

// The machine's fault is cleared as MESSD's Reset clears it: the core resets the drives' faults
// and frees the machine, or refuses while the cause remains (then 1000). Needs control.
bool IppServer::start_reset(const Pending& p) {
  const std::string_view name = ippdme::method_name(p.command);
  std::string why;
  if (!claim_control(false, why)) {
    spdlog::warn("I++ DME: ClearAllErrors cannot reset the machine: {}", why);
    fail(p.tag, ErrorCode::MachineInErrorState, name);
    return true;
  }
  core::Command c{core::CommandKind::Reset};
  c.client = kClientId;
  if (!gateway_.submit(c)) {
    fail(p.tag, ErrorCode::MachineInErrorState, name);
    return true;
  }
  step_ = Step::Reset;
  first_id_ = wait_id_ = 0;
  return false;
}

bool IppServer::start_home(const Pending& p) {
  const std::string_view name = ippdme::method_name(p.command);
  if (!take_machine(p)) return true;
  core::Command c{core::CommandKind::Home};
  c.client = kClientId;
  if (!gateway_.submit(c)) {
    fail(p.tag, ErrorCode::ErrorProcessingMethod, name);
    return true;
  }
  rest_.reset();
  step_ = Step::Home;
  first_id_ = wait_id_ = 0;
  return false;
}

// The machine still brakes (a stop, the operator's jog taken over, a retract): the command
// waits at the queue's front and starts again when the machine stands (retry()).
bool IppServer::wait_for_rest() {
  step_ = Step::Wait;
  return false;
}

void IppServer::retry() {
  if (step_ != Step::Wait || queue_.empty()) return;
  step_ = Step::None;
  if (run_front()) pump();  // else started (or waits again)
}

void IppServer::step_done() { end_step(std::nullopt); }
void IppServer::step_failed(ErrorCode code) { end_step(code); }

// The motion step of the queue's front ended: its `%` (after its error), the next command.
void IppServer::end_step(std::optional<ErrorCode> error) {
  step_ = Step::None;
  rest_.reset();
  if (queue_.empty()) return;
  const Pending p = queue_.front();
  queue_.pop_front();
  running_ = false;
  if (error) fail(p.tag, *error, ippdme::method_name(p.command));
  else finish(p.tag);
  pump();
}

void IppServer::segment_end(const core::Event& e) {
  if (step_ == Step::None || step_ == Step::Home || step_ == Step::Reset || step_ == Step::Wait || e.id < first_id_ || e.id > wait_id_)
    return;  // a step ended before
  if (step_ == Step::Scan) flush_scan_points();  // every point taken goes out before the end
  if (e.kind == core::EventKind::Failed) {
    step_failed(error_of(e.fail));
    return;
  }
  if (step_ == Step::Scan && e.id == wait_id_) {
    // An unknown contour ended where the loop backed off (its Done says where): the next plan
    // starts where the machine stands.
    if (e.probe_end && gateway_.ids_queued() == 0) gateway_.set_planning(false);
    step_done();
    return;
  }
  if (e.id != wait_id_) return;  // PtMeas: the move to the approach point
  if (step_ == Step::PtMeas) {
    rest_ = gateway_.pose_of(e.end);  // where the retract from the hit ended
    if (gateway_.ids_queued() == 0) gateway_.set_planning(false);  // the retract starts there
    if (!hit_seen_) {
      step_failed(ErrorCode::NoTouch);
      return;
    }
    // Retract (§9): < 0 back to the approach point; else that far from the touch along the
    // normal — at least the machine's own retract, which already freed the tip.
    const double r = tools_.act(Param::Retract);
    std::optional<Point3> target;
    if (r < 0) target = approach_m_;
    else if (r > gateway_.params().retract_distance + 1e-3)
      target = Point3{hit_tip_m_[0] + normal_m_[0] * r, hit_tip_m_[1] + normal_m_[1] * r, hit_tip_m_[2] + normal_m_[2] * r};
    if (!target) {
      step_done();
      return;
    }
    const planner::Line back{next_id(), pose_at(*target), tools_.act(Param::GoToSpeed), planner::ProbePhase::None,
                             tools_.lowered(Param::GoToAccel)};
    std::string why;
    if (const auto planned = plan_lines({back}, why); planned != Planned::Yes) {
      spdlog::info("I++ DME: PtMeas retract refused: {}", why);
      step_failed(refusal_error(planned));
      return;
    }
    step_ = Step::Retract;
    first_id_ = wait_id_ = back.id;
    return;
  }
  step_done();  // GoTo, Retract
}

void IppServer::dropped(core::FailReason why) {
  rest_.reset();
  if (step_ == Step::None || step_ == Step::Home || step_ == Step::Reset || step_ == Step::Wait) return;
  if (gateway_.in_loop_between(first_id_, wait_id_)) return;  // its own Failed will come
  if (step_ == Step::Scan) flush_scan_points();
  step_failed(error_of(why));
}

void IppServer::core_reply(const core::Event& e) {
  if (step_ == Step::Reset) {  // ClearAllErrors: the machine's fault is gone, or its cause remains
    if (e.refusal == core::Refusal::None) {
      error_state_ = false;
      last_error_.reset();
      step_done();
    } else {
      step_failed(ErrorCode::MachineInErrorState);
    }
    return;
  }
  if (step_ != Step::Home || e.refusal == core::Refusal::None) return;
  step_failed(ErrorCode::ErrorDuringHome);
}

void IppServer::homed() {
  if (step_ == Step::Home) step_done();
}

void IppServer::home_failed() {
  if (step_ == Step::Home) step_failed(ErrorCode::ErrorDuringHome);
}

std::vector<Value> IppServer::hit_values(const core::Event& e) const {
  const Point3 p = csy_.from_machine({e.p.x(), e.p.y(), e.p.z()});
  const Point3 n = csy_.vector_from_machine({-e.dir.x(), -e.dir.y(), -e.dir.z()});  // the surface normal: against the approach
  std::vector<Value> values;
  for (Item i : ptmeas_items_) {
    switch (i) {
      case Item::X:
      case Item::Y:
      case Item::Z: {
        const int c = i == Item::X ? 0 : i == Item::Y ? 1 : 2;
        values.push_back(Value::call(ippdme::item_name(i), {Value::of_fixed(p[c], kCoordinateDecimals)}));
        break;
      }
      case Item::IJK:
        values.push_back(Value::call("IJK", {Value::of_fixed(n[0], kVectorDecimals), Value::of_fixed(n[1], kVectorDecimals),
                                             Value::of_fixed(n[2], kVectorDecimals)}));
        break;
      case Item::ER: values.push_back(Value::call("ER", {Value::of_fixed(e.radius, kCoordinateDecimals)})); break;
      case Item::Q: values.push_back(Value::call("Q", {Value::of_integer(0)})); break;  // touches are not graded
      default:  // R, Tool.A/B/C: no rotary table, no probe head here (0)
        values.push_back(Value::call(ippdme::item_name(i), {Value::of_fixed(0.0, kCoordinateDecimals)}));
        break;
    }
  }
  return values;
}

void IppServer::hit(const core::Event& e) {
  if (!conn_ || !in_session_) return;
  if (step_ == Step::PtMeas && e.id == wait_id_ && !queue_.empty()) {
    hit_seen_ = true;
    const hal::Vec3 tip = e.p - e.radius * e.dir;  // the ball's centre at the touch
    hit_tip_m_ = {tip.x(), tip.y(), tip.z()};
    send(ippdme::format_data(queue_.front().tag, hit_values(e)));
    return;
  }
  if (user_enabled_ && !is_own_id(e.id))  // the operator's point, taken by hand or by jog
    send(ippdme::format_data(ippdme::kServerTag, {Value::call("PtMeas", hit_values(e))}));
}

void IppServer::key(const std::string& name) {
  if (conn_ && in_session_ && user_enabled_)
    send(ippdme::format_data(ippdme::kServerTag, {Value::call("KeyPress", {Value::of_string(name)})}));
}

void IppServer::tick() {
  retry();
  if (!daemon_ || !conn_) return;
  auto& d = *daemon_;
  const auto now = gateway_.snapshot().time;
  const double since = d.last_at ? std::chrono::duration<double>(now - *d.last_at).count() : 1e9;
  if (since < kMinReportPeriod) return;
  const Point3 p = tip_here();
  const double moved = norm({p[0] - d.last[0], p[1] - d.last[1], p[2] - d.last[2]});
  const bool due = !d.last_at || (d.time && since >= *d.time - 1e-9) || (d.dis && moved > *d.dis) ||
                   (!d.time && !d.dis && moved > 0);
  if (!due) return;
  d.last_at = now;
  d.last = p;
  send(ippdme::format_data(d.tag, position_payload(d.items)));
}

}  // namespace imess::net
