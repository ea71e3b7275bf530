// The I++ DME server as an observer of the machine: the fan-out's hooks, each handed to the
// session's own handling (ipp_motion.cpp, ipp_frames.cpp); every call runs under guarded().
#include "imess/net/ipp_server.hpp"

namespace imess::net {

void IppServer::segment_end(const core::Event& e) {
  gateway_.end_plan_if_idle();  // the queue ran out: the next plan starts where the machine stands
  own_segment_end(e);
}

bool IppServer::core_reply(const core::Event& e) {
  if (e.client != kClientId) return false;  // a MESSD client's
  loop_reply(e);
  return true;
}

void IppServer::hit(const core::Event& point, const JournaledHit&) { hit(point); }

void IppServer::state(core::Mode) { retry(); }

void IppServer::warning(const core::Event& e) {
  if (e.warning == core::Warning::HomingFailed) home_failed();
}

void IppServer::fault(const core::Event&) { home_failed(); }

void IppServer::frame_changed(const std::string&) { part_frame_changed(); }

}  // namespace imess::net
