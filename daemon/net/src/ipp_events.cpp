// The I++ DME server as an observer of the machine: the fan-out's hooks, each handed to the
// session's own handling (ipp_motion.cpp, ipp_frames.cpp); every call runs under its guard.
#include "imess/net/ipp_events.hpp"

#include "imess/net/ipp_server.hpp"

namespace imess::net {

bool IppEvents::guarded(std::string_view what, const std::function<void()>& f) { return ipp_.guarded(what, f); }

bool IppEvents::owns_segment(std::uint32_t id) const { return IppServer::is_own_id(id); }

void IppEvents::segment_end(const core::Event& e) {
  gateway_.end_plan_if_idle();  // the queue ran out: the next plan starts where the machine stands
  ipp_.segment_end(e);
}

bool IppEvents::core_reply(const core::Event& e) {
  if (e.client != IppServer::kClientId) return false;  // a MESSD client's
  ipp_.core_reply(e);
  return true;
}

void IppEvents::hit(const core::Event& point, const JournaledHit&) { ipp_.hit(point); }

void IppEvents::scanned(const core::Event& point, const JournaledHit&) { ipp_.scanned(point); }

void IppEvents::state(core::Mode) { ipp_.retry(); }

void IppEvents::warning(const core::Event& e) {
  if (e.warning == core::Warning::HomingFailed) ipp_.home_failed();
}

void IppEvents::fault(const core::Event&) { ipp_.home_failed(); }

void IppEvents::homed() { ipp_.homed(); }

void IppEvents::dropped(core::FailReason why) { ipp_.dropped(why); }

void IppEvents::move_report() { ipp_.tick(); }

void IppEvents::frame_changed(const std::string&) { ipp_.part_frame_changed(); }

bool IppEvents::listens_for_keys() const { return ipp_.listening_for_keys(); }

void IppEvents::key(const std::string& name) { ipp_.key(name); }

}  // namespace imess::net
