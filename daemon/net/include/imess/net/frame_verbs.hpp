// FrameVerbs: the part frames on the MESSD wire — Frames, Frame, PartPos, UseFrame, SetFrame,
// Align, DelFrame (docs/protocol.md, "Part frames"). The frames are FrameService's; Align
// reads its hits from the journal and fits them with the metrology library.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "imess/journal/journal.hpp"
#include "imess/net/frame_service.hpp"
#include "imess/net/motion_gateway.hpp"
#include "imess/net/session_hub.hpp"
#include "imess/protocol/commands.hpp"

namespace imess::net {

class FrameVerbs {
 public:
  FrameVerbs(SessionHub& sessions, FrameService& frames, MotionGateway& gateway, journal::Journal& journal, LogLimiter& log)
      : sessions_(sessions), frames_(frames), gateway_(gateway), journal_(journal), log_(log) {}
  void list_frames(Session& s, std::uint32_t slot);
  void show_frame(Session& s, std::uint32_t slot, std::string name);
  void part_pos(Session& s, std::uint32_t slot, std::string name);
  void use_frame(Session& s, std::uint32_t slot, std::string name);
  void set_frame(Session& s, std::uint32_t slot, const protocol::SetFrame& c);
  void align(Session& s, std::uint32_t slot, const protocol::Align& c);
  void del_frame(Session& s, std::uint32_t slot, const std::string& name);

 private:
  bool frames_usable(Session& s, std::uint32_t slot, std::string_view verb);
  bool last_hits(Session& s, std::uint32_t slot, const protocol::Align& c, const std::string& head,
                 std::array<std::string, 3>& sets, std::string& used);
  const metrology::Frame* frame_named(Session& s, std::uint32_t slot, std::string_view verb, std::string& name);
  void store_frame(Session& s, std::uint32_t slot, std::string_view verb, const std::string& name,
                   const metrology::Frame& frame, std::string_view extra);
  const hal::AxisLayout& layout() const noexcept { return gateway_.layout(); }
  void reply(Session& s, std::uint32_t slot, std::string lines) { sessions_.reply(s, slot, std::move(lines)); }

  SessionHub& sessions_;
  FrameService& frames_;
  MotionGateway& gateway_;
  journal::Journal& journal_;
  LogLimiter& log_;
};

}  // namespace imess::net
