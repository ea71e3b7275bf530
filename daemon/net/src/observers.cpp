// The observer fan-out: the empty hooks and the lookups over the list.
#include "imess/net/observers.hpp"

namespace imess::net {

bool MotionObserver::guarded(std::string_view, const std::function<void()>& f) {
  f();
  return true;
}
bool MotionObserver::owns_segment(std::uint32_t) const { return false; }
void MotionObserver::segment_end(const core::Event&) {}
void MotionObserver::unsent_failed(std::uint32_t, core::FailReason) {}
void MotionObserver::dropped(core::FailReason) {}
void MotionObserver::stopped(std::string_view) {}
bool MotionObserver::core_reply(const core::Event&) { return false; }
void MotionObserver::measured(const core::Event&) {}
void MotionObserver::hit(const core::Event&, const JournaledHit&) {}
void MotionObserver::scanned(const core::Event&, const JournaledHit&) {}
void MotionObserver::state(core::Mode) {}
void MotionObserver::limit(const core::Event&) {}
void MotionObserver::warning(const core::Event&) {}
void MotionObserver::fault(const core::Event&) {}
void MotionObserver::homed() {}
void MotionObserver::drained() {}
void MotionObserver::move_report() {}
void MotionObserver::frame_changed(const std::string&) {}
void MotionObserver::control_changed(const std::optional<Controller>&) {}
void MotionObserver::control_taken(const Controller&, const Controller&) {}
bool MotionObserver::listens_for_keys() const { return false; }
void MotionObserver::key(const std::string&) {}

MotionObserver* Observers::owner_of(std::uint32_t id) const {
  for (MotionObserver* o : list_)
    if (o != fallback_ && o->owns_segment(id)) return o;
  return fallback_;
}

bool Observers::any_listens_for_keys() const {
  for (const MotionObserver* o : list_)
    if (o->listens_for_keys()) return true;
  return false;
}

}  // namespace imess::net
