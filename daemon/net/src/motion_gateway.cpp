// The gateway's side of the loop's rings: the event drain and its fan-out to the observers,
// the readings of the machine every front end shares.
#include "imess/net/motion_gateway.hpp"

#include "imess/core/path_machine.hpp"

namespace imess::net {

using core::EventKind;

MotionGateway::MotionGateway(boost::asio::io_context& io, core::MotionCore& core, Observers& observers, LogLimiter& log,
                             bool log_motion)
    : io_(io),
      core_(core),
      observers_(observers),
      log_(log),
      log_motion_(log_motion),
      planner_(core::path_machine(core.config()), core::path_options(core.config())) {}

planner::Pose MotionGateway::pose_of(const core::AxisVec& v) const noexcept {
  planner::Pose p{};
  for (int a = 0; a < layout().count; ++a) p[a] = v[a];
  return p;
}

planner::Pose target_of(const hal::AxisLayout& layout, const protocol::PathWords& w, const planner::Pose& start) noexcept {
  planner::Pose target = start;
  for (int a = 0; a < layout.count; ++a)
    if (const auto& word = *w.axis(layout.letters[a])) target[a] = *word;
  return target;
}

const protocol::PathWords* words_of(const QueuedCommand& c) noexcept {
  if (const auto* m = std::get_if<protocol::MoveTo>(&c)) return &m->words;
  if (const auto* a = std::get_if<protocol::ArcTo>(&c)) return &a->words;
  if (const auto* p = std::get_if<protocol::Probe>(&c)) return &p->words;
  return nullptr;
}

std::size_t MotionGateway::pump_events() {
  core::Event e;
  std::size_t drained = 0;
  while (core_.events().pop(e)) {
    ++drained;
    switch (e.kind) {
      case EventKind::Reply: {
        // The first observer whose client it was answers it (a client that left: nobody).
        bool taken = false;
        observers_.each("CoreReply", [&](MotionObserver& o) {
          if (!taken) taken = o.core_reply(e);
        });
        break;
      }
      case EventKind::MeasPt:
      case EventKind::ScanPt: observers_.each("Hit", [&](MotionObserver& o) { o.measured(e); }); break;
      case EventKind::State: observers_.each("Retry", [&](MotionObserver& o) { o.state(e.mode); }); break;
      case EventKind::Limit: observers_.each("Limit", [&](MotionObserver& o) { o.limit(e); }); break;
      case EventKind::Warn: observers_.each("HomeFailed", [&](MotionObserver& o) { o.warning(e); }); break;
      case EventKind::Fault: observers_.each("HomeFailed", [&](MotionObserver& o) { o.fault(e); }); break;
      case EventKind::Homed: observers_.each("Homed", [&](MotionObserver& o) { o.homed(); }); break;
      case EventKind::Done:
      case EventKind::Failed: on_segment_end(e); break;
      case EventKind::QueueDropped:  // a limit, fault or hit: what the loop never received fails too
        drops_ = e.id;
        drop_planned(e.fail);
        break;
      case EventKind::QueueLow:  // the loop holds only the segment it runs: end the plan at rest
        planner_.flush();
        feed_segments();
        break;
    }
  }
  observers_.each("Drained", [](MotionObserver& o) { o.drained(); });
  return drained;
}

}  // namespace imess::net
