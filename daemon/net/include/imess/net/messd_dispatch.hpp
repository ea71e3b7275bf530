// MessdDispatch: the MESSD line protocol's requests — a client's line parsed (protocol/),
// checked for control, and handed to the service that answers it: the MotionGateway (motion
// commands, queued moves), ControlService, HitService (Replay, Qualify), ProgramRunner,
// FrameVerbs, PositionStream (Stream), StatsReport; the rest (Hello, Help, Status, Get / Set,
// Key, JogAx) answered here. Every request gets exactly one reply in its slot.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

#include "imess/net/control_service.hpp"
#include "imess/net/frame_verbs.hpp"
#include "imess/net/hit_service.hpp"
#include "imess/net/motion_gateway.hpp"
#include "imess/net/observers.hpp"
#include "imess/net/position_stream.hpp"
#include "imess/net/program_runner.hpp"
#include "imess/net/server_config.hpp"
#include "imess/net/session_hub.hpp"
#include "imess/net/stats_report.hpp"
#include "imess/protocol/verb_spec.hpp"

namespace imess::net {

// The services the MESSD front end drives (all owned by net::Server).
struct MessdServices {
  SessionHub& sessions;
  MotionGateway& gateway;
  ControlService& control;
  HitService& hits;
  ProgramRunner& programs;
  FrameVerbs& frames;
  PositionStream& stream;
  StatsReport& stats;
  Observers& observers;
  LogLimiter& log;
};

class MessdDispatch {
 public:
  MessdDispatch(ServerConfig& config, MessdServices services);
  void on_line(Session& s, const protocol::FramedLine& line);
  void gone(Session& s);  // the client left: its control is lost (the dead-man)

 private:
  // messd_dispatch.cpp
  void on_command(Session& s, std::uint32_t slot, const protocol::Command& cmd);
  bool to_core(Session& s, std::uint32_t slot, core::Command c);
  void stop_request(Session& s, std::uint32_t slot);
  void hello(Session& s, std::uint32_t slot, const protocol::Hello& c);
  void help(Session& s, std::uint32_t slot);
  void press_key(Session& s, std::uint32_t slot, const std::string& name);
  void get_param(Session& s, std::uint32_t slot, const protocol::Get& c);
  void set_param(Session& s, std::uint32_t slot, const protocol::Set& c);
  void qualify(Session& s, std::uint32_t slot, const protocol::Qualify& c);
  void verdict(Session& s, std::uint32_t slot, const protocol::Verdict& c);
  std::string status_line();
  // messd_control.cpp: the MESSD side of control
  bool allowed(Session& s, const protocol::Command& cmd, std::uint32_t slot);
  void take(Session& s, std::uint32_t slot, const protocol::Take& t);
  void release(Session& s, std::uint32_t slot);
  Controller controller(Session& s) const;
  // messd_queue.cpp: queued moves and outputs on the wire
  void queue_command(Session& s, std::uint32_t slot, const QueuedCommand& c);
  void queue_status(Session& s, std::uint32_t slot);
  void outputs_status(Session& s, std::uint32_t slot);
  std::string output_names() const;
  // messd_programs.cpp: Upload's lines, Abort
  void begin_upload(Session& s, std::uint32_t slot, const std::string& name);
  void upload_line(Session& s, const protocol::FramedLine& line);
  void abort_program(Session& s, std::uint32_t slot);
  // axes.cpp: the machine's axes on the wire
  std::string no_axis_text(char letter) const;
  bool machine_vector(Session& s, std::uint32_t slot, const protocol::Xyz& p, core::AxisVec& out, unsigned& given);
  bool axes_known(Session& s, std::uint32_t slot, const protocol::PathWords& w);
  void jog_axes(Session& s, std::uint32_t slot, const protocol::JogAx& c);
  std::string machine_help_line(const protocol::VerbSpec& v) const;

  const hal::AxisLayout& layout() const noexcept { return gateway_.layout(); }
  void reply(Session& s, std::uint32_t slot, std::string lines) { sessions_.reply(s, slot, std::move(lines)); }
  ProgramRunner::Answer answer(Session& s, std::uint32_t slot) {
    return [this, &s, slot](std::string lines) { reply(s, slot, std::move(lines)); };
  }

  ServerConfig& config_;
  SessionHub& sessions_;
  MotionGateway& gateway_;
  ControlService& control_;
  HitService& hits_;
  ProgramRunner& programs_;
  FrameVerbs& frames_;
  PositionStream& stream_;
  StatsReport& stats_;
  Observers& observers_;
  LogLimiter& log_;
};

}  // namespace imess::net
