// The io thread's event fan-out: what happens to the machine (the motion loop's events, hits
// after the journal, the part frame, control, the operator's keys) reaches every front end
// and service through one list of observers, in the order they were added. No front end is
// wired into another: a third one (a web panel, a bridge) is one more `add`.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "imess/core/core_types.hpp"
#include "imess/net/control.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

// A measured point as it left the journal: its record (seq numbered) and the Hit line sent.
struct JournaledHit {
  protocol::HitMsg msg;
  std::string line;
};

// Every hook has an empty default: an observer overrides what it cares about.
class MotionObserver {
 public:
  virtual ~MotionObserver() = default;
  // Runs one hook. An observer whose failure must end only itself (the I++ DME session:
  // IppServer::guarded) catches here; the default lets the exception through.
  virtual bool guarded(std::string_view what, const std::function<void()>& f);

  // Queued moves: the observer that claims an id gets its Done / Failed (the first that
  // claims it; ids nobody claims are the fallback's, MotionGateway::set_fallback).
  virtual bool owns_segment(std::uint32_t id) const;
  virtual void segment_end(const core::Event& e);              // Done / Failed of an own id
  virtual void unsent_failed(std::uint32_t id, core::FailReason why);  // an own id the loop never received
  virtual void dropped(core::FailReason why);                  // what was planned was dropped (a limit, a stop ...)
  virtual void stopped(std::string_view who);                  // a stop (StopMv, Abort, the dead-man ...) after the drop
  // The loop's answer to a command; true when it was this observer's client's.
  virtual bool core_reply(const core::Event& e);
  virtual void measured(const core::Event& e);                 // the raw MeasPt or ScanPt (the hit service journals it)
  virtual void hit(const core::Event& point, const JournaledHit& h);  // after the journal
  virtual void scanned(const core::Event& point, const JournaledHit& h);  // a scan's point, after the journal
  virtual void state(core::Mode mode);
  virtual void limit(const core::Event& e);
  virtual void warning(const core::Event& e);
  virtual void fault(const core::Event& e);
  virtual void homed();
  virtual void drained();                                      // after every drain of the event ring
  virtual void move_report();                                  // the report timer's tick (I++ move reports)
  // Not of the loop: the active part frame, the owner of the machine, the operator's keys.
  virtual void frame_changed(const std::string& active);
  virtual void control_changed(const std::optional<Controller>& owner);
  virtual void control_taken(const Controller& was, const Controller& by);  // Take force / a session's take-over
  virtual bool listens_for_keys() const;
  virtual void key(const std::string& name);
};

// The list; each call goes through the observer's guarded().
class Observers {
 public:
  void add(MotionObserver& o) { list_.push_back(&o); }
  void set_fallback(MotionObserver& o) { fallback_ = &o; }
  // Calls f(observer) for each, in order, guarded as `what`.
  template <class F>
  void each(std::string_view what, F&& f) {
    const auto list = list_;  // a hook may add no observer, but stay safe against it
    for (MotionObserver* o : list) o->guarded(what, [&] { f(*o); });
  }
  // The observer that claims a queued id (else the fallback; nullptr when there is none).
  MotionObserver* owner_of(std::uint32_t id) const;
  MotionObserver* fallback() const { return fallback_; }
  bool any_listens_for_keys() const;

 private:
  std::vector<MotionObserver*> list_;
  MotionObserver* fallback_ = nullptr;
};

}  // namespace imess::net
