// Programs on the MESSD wire, beside ProgramRunner: an Upload's lines up to '.' (kept in the
// session), and Abort (a stop for anyone, program or not).
#include "imess/net/messd_dispatch.hpp"
#include "imess/protocol/messages.hpp"

namespace imess::net {

using protocol::ErrorCode;
using protocol::format_err;
using protocol::format_ok;

void MessdDispatch::begin_upload(Session& s, std::uint32_t slot, const std::string& name) {
  if (auto why = program_name_problem(name); !why.empty()) {
    reply(s, slot, format_err(ErrorCode::BadValue, "Upload " + name + ": expected " + why));
    return;
  }
  s.info().upload = ProgramUpload{name, {}, 0, {}};
  reply(s, slot, format_ok("Upload", name + " send the lines, then a line '.'"));
}

// A line while an Upload is open: part of the program, or its end '.'.
void MessdDispatch::upload_line(Session& s, const protocol::FramedLine& line) {
  auto& up = *s.info().upload;
  const auto& pc = config_.programs;
  if (line.text != ".") {
    if (!up.refused.empty()) return;  // keep reading to the '.', answer then
    const std::string at = "line " + std::to_string(up.lines + 1) + ": ";
    if (line.overlong) up.refused = at + "longer than " + std::to_string(protocol::kMaxLineLength) + " characters";
    else if (up.lines >= pc.max_lines) up.refused = at + "more than " + std::to_string(pc.max_lines) + " lines";
    else if (up.text.size() + line.text.size() + 1 > pc.max_bytes) up.refused = at + "more than " + std::to_string(pc.max_bytes) + " bytes";
    if (!up.refused.empty()) return;
    up.text.append(line.text);
    up.text.push_back('\n');
    ++up.lines;
    return;
  }
  ProgramUpload done = std::move(up);
  s.info().upload.reset();
  const std::uint32_t slot = s.reserve_reply();
  if (!done.refused.empty()) {
    reply(s, slot, format_err(ErrorCode::BadProgram, "Upload " + done.name + ": " + done.refused + "; accepted up to " +
                                                         std::to_string(pc.max_lines) + " lines, " + std::to_string(pc.max_bytes) +
                                                         " bytes, lines of " + std::to_string(protocol::kMaxLineLength) +
                                                         " characters; the program was discarded"));
    return;
  }
  programs_.finish_load(s.id(), "Upload", done.name, std::move(done.text), answer(s, slot));
}

void MessdDispatch::abort_program(Session& s, std::uint32_t slot) {
  // Abort is a stop for anyone, program or not: without a program it is a StopMv, so it
  // also drops what the planner holds. (It was core_.request_stop() alone: the loop failed
  // the segments it had, then the queue's tail that the planner still held was sent after
  // the stop and moved the machine again — found by tests/golden/test_program_properties.cpp.)
  gateway_.stop("Abort");
  reply(s, slot, format_ok("Abort"));
}

}  // namespace imess::net
