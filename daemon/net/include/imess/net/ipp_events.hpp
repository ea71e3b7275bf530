// IppEvents: the I++ DME session as an observer of the machine — each hook of the fan-out
// handed to the IppServer's own handling, under its guard (an exception ends the session,
// never the io thread).
#pragma once
#include <string>

#include "imess/net/motion_gateway.hpp"
#include "imess/net/observers.hpp"

namespace imess::net {

class IppServer;

class IppEvents : public MotionObserver {
 public:
  IppEvents(IppServer& ipp, MotionGateway& gateway) : ipp_(ipp), gateway_(gateway) {}
  bool guarded(std::string_view what, const std::function<void()>& f) override;
  bool owns_segment(std::uint32_t id) const override;  // the session's ids (IppServer::kIdBase on)
  void segment_end(const core::Event& e) override;
  bool core_reply(const core::Event& e) override;      // to the session's client number
  void hit(const core::Event& point, const JournaledHit& journaled) override;
  void scanned(const core::Event& point, const JournaledHit& journaled) override;
  void state(core::Mode mode) override;                // a move waiting for the machine to stand
  void warning(const core::Event& e) override;         // HomingFailed
  void fault(const core::Event& e) override;
  void homed() override;
  void dropped(core::FailReason why) override;
  void move_report() override;
  void frame_changed(const std::string& active) override;  // PartCsy follows
  bool listens_for_keys() const override;
  void key(const std::string& name) override;

 private:
  IppServer& ipp_;
  MotionGateway& gateway_;
};

}  // namespace imess::net
