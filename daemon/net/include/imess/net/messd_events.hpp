// MessdEvents: the MESSD front end as an observer — the machine's events as MESSD lines to
// every client (Done / Failed of the queued moves, which it owns as the gateway's fallback,
// Hit / MeasPt / PartPt, State, Limit, Warn, Fault, Homed, Frame, Control) and the loop's
// replies into their clients' slots (docs/protocol.md, "Events").
#pragma once
#include <optional>
#include <string>

#include "imess/net/frame_service.hpp"
#include "imess/net/motion_gateway.hpp"
#include "imess/net/observers.hpp"
#include "imess/net/session_hub.hpp"

namespace imess::net {

class MessdEvents : public MotionObserver {
 public:
  MessdEvents(SessionHub& sessions, const MotionGateway& gateway, const FrameService& frames, LogLimiter& log, bool log_motion)
      : sessions_(sessions), gateway_(gateway), frames_(frames), log_(log), log_motion_(log_motion) {}

  void segment_end(const core::Event& e) override;
  void unsent_failed(std::uint32_t id, core::FailReason why) override;
  bool core_reply(const core::Event& e) override;
  void hit(const core::Event& point, const JournaledHit& h) override;
  void scanned(const core::Event& point, const JournaledHit& h) override;  // the Scan line alone
  void state(core::Mode mode) override;
  void limit(const core::Event& e) override;
  void warning(const core::Event& e) override;
  void fault(const core::Event& e) override;
  void homed() override;
  void frame_changed(const std::string& active) override;
  void control_changed(const std::optional<Controller>& owner) override;
  void control_taken(const Controller& was, const Controller& by) override;

 private:
  void send_part_point(const protocol::HitMsg& hit);  // PartPt: the hit in the active part frame

  SessionHub& sessions_;
  const MotionGateway& gateway_;
  const FrameService& frames_;
  LogLimiter& log_;
  bool log_motion_;
};

}  // namespace imess::net
