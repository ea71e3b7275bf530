// Programs on the io thread: the programs folder, Load and Upload (translated and checked
// completely against this machine before anything moves), Run (items planned ahead of the
// loop through the same planner and segment ring as queued moves), M0, probes, Abort, and
// the Block / ProgPause / ProgEnd events. Rules in docs/programs.md ("Running programs").
#include <spdlog/spdlog.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <numbers>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "imess/net/program_check.hpp"
#include "imess/net/server.hpp"
#include "imess/net/wording.hpp"
#include "imess/protocol/messages.hpp"
#include "imess/protocol/numbers.hpp"

namespace imess::net {

using protocol::ErrorCode;
using protocol::format_err;
using protocol::format_event;
using protocol::format_ok;

const char* state_name(ProgramState s) {
  switch (s) {
    case ProgramState::None: return "none";
    case ProgramState::Loaded: return "loaded";
    case ProgramState::Running: return "running";
    case ProgramState::Paused: return "paused";
    case ProgramState::Ended: return "ended";
  }
  return "none";
}

const char* outcome_name(ProgramOutcome o) {
  switch (o) {
    case ProgramOutcome::Ok: return "ok";
    case ProgramOutcome::Failed: return "failed";
    case ProgramOutcome::Aborted: return "aborted";
  }
  return "failed";
}

namespace {
// Program items planned ahead of the loop: enough for the planner's look-ahead over short
// segments, few enough that a stop drops little.
constexpr std::size_t kPlanAhead = 48;
// Block events at most 10 a second, timed by the motion loop's clock (virtual in tests, so a
// transcript replays the same events).
constexpr auto kBlockEvery = std::chrono::milliseconds(100);
// The translators name outputs by these tags; resolve_outputs() turns them into the
// machine's output numbers (M3/M5 the spindle output, M62–M65 P<n> the n-th listed output).
constexpr std::uint16_t kSpindleTag = 60000;
constexpr std::uint16_t kMistTag = 60001, kFloodTag = 60002;
constexpr std::uint16_t kDigitalTag = 61000;

// A name in the programs folder: one file name, printable, no path.
std::string name_problem(const std::string& name) {
  if (name.size() > 255) return "a name of at most 255 characters";
  for (char c : name)
    if (c == '/' || c == '\\' || static_cast<unsigned char>(c) < 33 || static_cast<unsigned char>(c) > 126)
      return "a file name without '/', '\\', blanks or control characters";
  if (name.find("..") != std::string::npos || name.front() == '.') return "a file name not starting with '.' and without '..'";
  if (!programs::language_of(name))
    return std::string("a name ending in one of ") + programs::kExtensions + " (it gives the language)";
  return {};
}

}  // namespace

programs::Setup program_setup(const ProgramConfig& pc, const core::CoreConfig& core, const planner::Machine& machine,
                              const planner::Pose& start) {
  programs::Setup s;
  s.machine = machine;
  s.start = start;
  for (std::size_t a = 0; a < pc.home.size() && a < planner::kMaxAxes; ++a) s.gcode.home[a] = pc.home[a];
  for (std::size_t a = 0; a < pc.g30.size() && a < planner::kMaxAxes; ++a) s.gcode.g30[a] = pc.g30[a];
  s.gcode.block_delete = pc.block_delete;
  if (!pc.spindle.empty()) s.gcode.spindle_output = kSpindleTag;
  if (!pc.mist.empty()) s.gcode.mist_output = kMistTag;
  if (!pc.flood.empty()) s.gcode.flood_output = kFloodTag;
  s.gcode.tool_change_pause = pc.tool_change_pause;
  s.gcode.digital_output_base = kDigitalTag;
  s.gcode.digital_output_count = static_cast<std::uint16_t>(pc.outputs.size());
  s.hpgl.origin_x = pc.origin_x;
  s.hpgl.origin_y = pc.origin_y;
  s.hpgl.feed = pc.hpgl_feed;
  s.hpgl.pen_up_z = pc.pen_up_z;
  s.hpgl.pen_down_z = pc.pen_down_z;
  s.hpgl.pen_feed = pc.pen_feed;
  if (pc.pen != "z") {
    s.hpgl.pen = programs::HpglOptions::Pen::Output;
    const auto* out = core::find_output(core, pc.pen);
    s.hpgl.pen_output = out ? static_cast<std::uint16_t>(out->number) : 0;
  }
  s.mrm.a_axis = pc.mrm_a;
  s.mrm.b_axis = pc.mrm_b;
  s.mrm.c_axis = pc.mrm_c;
  const auto* grip = core::find_output(core, pc.gripper);
  s.mrm.gripper_output = grip ? static_cast<std::uint16_t>(grip->number) : 0;
  return s;
}

bool work_offsets_from_frames(const PartFrames& frames, const hal::AxisLayout& layout, programs::GcodeOptions& g,
                              std::string& error) {
  for (int i = 0; i < programs::kWorkOffsets; ++i) {
    const std::string name(programs::kWorkOffsetNames[static_cast<std::size_t>(i)]);
    const auto* f = frames.find(name);
    if (!f) continue;
    const double turned = Eigen::AngleAxisd(f->rotation()).angle();
    if (turned > 1e-9) {
      error = "line 1:1: not configured: found the part frame " + name + " turned by " + std::to_string(turned * 180 / std::numbers::pi) +
              " degrees, accepted frames G54 to G59.3 that only shift the machine's axes (SetFrame " + name + " O x y z)";
      return false;
    }
    for (int c = 0; c < 3; ++c)
      if (const int a = layout.cartesian_axis(c); a >= 0) g.work_offsets[static_cast<std::size_t>(i)][static_cast<std::size_t>(a)] = f->translation()[c];
    if (frames.active() == name) g.work_offset = i;
  }
  return true;
}

bool resolve_program_outputs(std::vector<programs::Item>& items, const ProgramConfig& pc, const core::CoreConfig& core,
                             std::string& error) {
  for (auto& item : items) {
    auto* o = std::get_if<planner::SetOutput>(&item.step);
    if (!o) continue;
    const core::OutputSettings* out = nullptr;
    if (o->output == kSpindleTag) {
      out = core::find_output(core, pc.spindle);
    } else if (o->output == kMistTag || o->output == kFloodTag) {
      out = core::find_output(core, o->output == kMistTag ? pc.mist : pc.flood);
    } else if (o->output >= kDigitalTag && static_cast<std::size_t>(o->output - kDigitalTag) < pc.outputs.size()) {
      out = core::find_output(core, pc.outputs[o->output - kDigitalTag]);
    } else {
      for (int i = 0; i < core.output_count; ++i)
        if (core.outputs[i].number == o->output) out = &core.outputs[i];
    }
    if (!out) {
      std::string names;
      for (int i = 0; i < core.output_count; ++i) names += (names.empty() ? "" : ", ") + std::string(core.outputs[i].name_view());
      error = "line " + std::to_string(item.line) + ":1: not configured: found a switch of output " +
              std::to_string(o->output) + ", accepted the machine's outputs (" + (names.empty() ? "none" : names) +
              ") as the programs section maps them (spindle, mist, flood, outputs, pen, gripper)";
      return false;
    }
    o->output = static_cast<std::uint16_t>(out->number);
    o->hold = out->settle_s;
  }
  return true;
}

// Translates and checks the program from `start`; the items of the run in `items`.
bool Server::check_program_text(const LoadedProgram& p, const planner::Pose& start, std::vector<programs::Item>& items,
                                programs::Check& check, std::string& error) const {
  return check_program_for({config_.programs, core_.config(), planner_.machine(), planner_.options(), &frames_}, p,
                           start, items, check, error);
}

bool Server::program_busy(Session& s, std::uint32_t slot, std::string_view verb) {
  if (!program_.running()) return false;
  reply(s, slot, format_err(ErrorCode::Busy, std::string(verb) + ": program " + program_.loaded->name +
                                                 " is running; Pause, Abort or wait for its ProgEnd"));
  return true;
}

void Server::list_programs(Session& s, std::uint32_t slot) {
  const std::string& folder = config_.programs.folder;
  if (folder.empty()) {
    reply(s, slot, format_ok("Programs"));
    return;
  }
  std::vector<std::string> names;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (it->is_regular_file(ec) && name_problem(name).empty()) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  std::string line;
  for (const auto& n : names) line += (line.empty() ? "" : " ") + n;
  reply(s, slot, format_ok("Programs", line));
}

void Server::load_program(Session& s, std::uint32_t slot, const std::string& name) {
  if (program_busy(s, slot, "Load")) return;
  if (auto why = name_problem(name); !why.empty()) {
    reply(s, slot, format_err(ErrorCode::BadValue, "Load " + name + ": expected " + why));
    return;
  }
  const std::string& folder = config_.programs.folder;
  if (folder.empty()) {
    reply(s, slot, format_err(ErrorCode::BadValue, "Load " + name +
                                                       ": no programs folder is configured (programs.folder); Upload sends a program over the connection"));
    return;
  }
  const auto path = std::filesystem::path(folder) / name;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || !std::filesystem::is_regular_file(path, ec)) {
    reply(s, slot, format_err(ErrorCode::BadValue, "Load " + name + ": no such program in the programs folder; Programs lists them"));
    return;
  }
  // A symbolic link may point anywhere; only a file inside the folder is a program (an error
  // message quotes what it read, so no other file of the controller is shown to a client).
  const auto real = std::filesystem::canonical(path, ec);
  const auto root = std::filesystem::canonical(folder, ec);
  const auto rel = real.lexically_relative(root);
  if (ec || rel.empty() || *rel.begin() == "..") {
    reply(s, slot, format_err(ErrorCode::BadValue, "Load " + name + ": the file lies outside the programs folder (a link); accepted: files in the folder"));
    return;
  }
  if (size > config_.programs.max_bytes) {
    reply(s, slot, format_err(ErrorCode::BadProgram, "Load " + name + ": " + std::to_string(size) + " bytes; accepted up to " +
                                                         std::to_string(config_.programs.max_bytes)));
    return;
  }
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) {
    reply(s, slot, format_err(ErrorCode::BadValue, "Load " + name + ": the file could not be read"));
    return;
  }
  finish_load(s, slot, "Load", name, std::move(text));
}

// Load and the end of an Upload: translated and checked from where the machine stands.
void Server::finish_load(Session& s, std::uint32_t slot, std::string_view verb, const std::string& name, std::string text) {
  if (program_busy(s, slot, verb)) return;
  LoadedProgram p{name, *programs::language_of(name), std::move(text), {}};
  std::vector<programs::Item> items;
  std::string error;
  const auto& snap = core_.snapshot();
  if (!check_program_text(p, pose_of(snap.position), items, p.check, error)) {
    reply(s, slot, format_err(ErrorCode::BadProgram, std::string(verb) + " " + name + ": " + error));
    return;
  }
  const auto& c = p.check;
  std::string summary = name + " Lang " + programs::language_name(p.lang) + " Lines " + std::to_string(c.lines) +
                        " Blocks " + std::to_string(c.blocks) + " Segments " + std::to_string(c.segments) + " Length ";
  protocol::append_fixed(summary, c.length, 3);
  summary += " Time ";
  protocol::append_fixed(summary, c.time, 1);
  program_.loaded = std::move(p);
  program_.state = ProgramState::Loaded;
  program_.items.clear();
  log_limited(spdlog::level::info, "program", "client " + std::to_string(s.id()) + " loaded program " + summary);
  reply(s, slot, format_ok("Load", summary));
}

void Server::begin_upload(Session& s, std::uint32_t slot, const std::string& name) {
  if (auto why = name_problem(name); !why.empty()) {
    reply(s, slot, format_err(ErrorCode::BadValue, "Upload " + name + ": expected " + why));
    return;
  }
  s.info().upload = ProgramUpload{name, {}, 0, {}};
  reply(s, slot, format_ok("Upload", name + " send the lines, then a line '.'"));
}

// A line while an Upload is open: part of the program, or its end '.'.
void Server::upload_line(Session& s, const protocol::FramedLine& line) {
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
  finish_load(s, slot, "Upload", done.name, std::move(done.text));
}

void Server::run_program(Session& s, std::uint32_t slot, bool detached) {
  if (program_busy(s, slot, "Run")) return;
  if (!program_.loaded) {
    reply(s, slot, format_err(ErrorCode::BadValue, "Run: no program loaded; Load or Upload one first"));
    return;
  }
  const auto& snap = core_.snapshot();
  if ((snap.mode != core::Mode::Idle && snap.mode != core::Mode::Free) || planning_ || !in_loop_.empty() || program_.tail) {
    reply(s, slot, format_err(ErrorCode::Busy, "Run: the machine is busy (State " + std::string(mode_name(snap.mode)) +
                                                   (snap.mode == core::Mode::Fault
                                                        ? "); clear the fault with Reset first"
                                                        : "); run when it stands and the queue is empty, or StopMv")));
    return;
  }
  const planner::Pose here = pose_of(snap.position);
  std::vector<programs::Item> items;
  std::string error;
  if (!check_program_text(*program_.loaded, here, items, program_.loaded->check, error)) {
    reply(s, slot, format_err(ErrorCode::BadProgram, "Run " + program_.loaded->name + ": from where the machine stands: " + error));
    return;
  }
  planner_.set_position(here);
  planning_ = true;
  program_.items = std::move(items);
  program_.next = 0;
  program_.detached = detached;
  program_.feeding_done = false;
  program_.probe.reset();
  program_.pause_at.reset();
  program_.shown_block = 0;
  program_.done_block = 0;
  program_.state = ProgramState::Running;
  log_limited(spdlog::level::info, "program", "client " + std::to_string(s.id()) + " runs program " + program_.loaded->name +
                                                  (detached ? " detached" : ""));
  reply(s, slot, format_ok("Run", program_.loaded->name));
  feed_program();
  feed_segments();
  show_block(false);
  program_progress();
  schedule_flush_check();
}

void Server::abort_program(Session& s, std::uint32_t slot) {
  // Abort is a stop for anyone, program or not: without a program it is a StopMv, so it
  // also drops what the planner holds. (It was core_.request_stop() alone: the loop failed
  // the segments it had, then the queue's tail that the planner still held was sent after
  // the stop and moved the machine again — found by tests/golden/test_program_properties.cpp.)
  stop_machine("Abort");
  reply(s, slot, format_ok("Abort"));
}

void Server::program_status(Session& s, std::uint32_t slot) {
  if (!program_.loaded) {
    reply(s, slot, format_ok("Program", "none none Line 0 Block 0/0"));
    return;
  }
  const std::size_t block = program_.shown_block;
  const std::size_t total = program_.running() || program_.state == ProgramState::Ended ? program_.items.size()
                                                                                         : program_.loaded->check.blocks;
  const int line = block > 0 && block <= program_.items.size() ? program_.items[block - 1].line : 0;
  const bool held = program_.state == ProgramState::Running && core_.snapshot().path_held;
  reply(s, slot, format_ok("Program", program_.loaded->name + " " + (held ? "paused" : state_name(program_.state)) +
                                          " Line " + std::to_string(line) + " Block " + std::to_string(block) + "/" +
                                          std::to_string(total)));
}

// Resume: a program waiting at its M0 goes on (the feed hold, if any, is ended by the loop).
void Server::resume_program() {
  if (program_.state != ProgramState::Paused) return;
  program_.state = ProgramState::Running;
  program_.pause_at.reset();
  feed_program();
  feed_segments();
  show_block(false);
  program_progress();
  schedule_flush_check();
}

// Items into the planner while the loop holds less than kPlanAhead of them; never past a
// probe whose end has not come (the rest starts where it ended) or an M0.
void Server::feed_program() {
  auto& pr = program_;
  while (pr.state == ProgramState::Running && !pr.feeding_done && !pr.probe && !pr.pause_at &&
         unsent_.size() + in_loop_.size() < kPlanAhead) {
    const std::size_t i = pr.next;
    if (i >= pr.items.size() || std::holds_alternative<programs::End>(pr.items[i].step)) {
      pr.feeding_done = true;
      planner_.flush();
      break;
    }
    const programs::Item& item = pr.items[i];
    ++pr.next;
    if (std::holds_alternative<programs::Pause>(item.step)) {
      pr.pause_at = i;
      planner_.flush();
      break;
    }
    const auto req = programs::request_of(item, programs::item_id(i), planner_.position(), planner_.machine());
    if (!req) continue;
    planning_ = true;
    if (const auto res = planner_.append(*req); !res.ok()) {  // the check passed from the start: only after a probe
      const std::string why = planner::describe(res, planner_.machine());
      fail_program(item.line, "refused " + why.substr(why.find(": ") + 2));
      return;
    }
    unsent_.push_back(programs::item_id(i));
    if (std::holds_alternative<programs::Probe>(item.step)) {
      pr.probe = programs::item_id(i);
      planner_.flush();  // the machine stops at the hit: the probe ends at rest
    }
  }
}

// After every step of the run: an M0 reached (everything before it done), or the end.
void Server::program_progress() {
  auto& pr = program_;
  if (!pr.running()) return;
  const bool empty = unsent_.empty() && in_loop_.empty() && planner_.pending() == 0 && planner_.ready() == 0;
  if (!empty || pr.probe) return;
  if (pr.pause_at && pr.state == ProgramState::Running) {
    pr.state = ProgramState::Paused;
    show_block(true);
    pr.shown_block = *pr.pause_at + 1;  // Program names the M0 while it waits there
    const auto& item = pr.items[*pr.pause_at];
    const auto* pause = std::get_if<programs::Pause>(&item.step);
    broadcast(format_event("ProgPause", pr.loaded->name + " " + std::to_string(item.line) + " " + (pause ? pause->reason : "M0")));
    return;
  }
  if (pr.feeding_done) {
    const int line = pr.next < pr.items.size() ? pr.items[pr.next].line : pr.items.empty() ? 0 : pr.items.back().line;
    end_program(ProgramOutcome::Ok, line, "end");
  }
}

// A Done or Failed of the program's ids (true), or not the program's (false).
bool Server::program_segment_end(const core::Event& e) {
  auto& pr = program_;
  if (!pr.running() && !pr.tail) return false;
  // No queue of a client can start while a program runs or its last segments drain, so every
  // id the loop reports now is the program's.
  if (!pr.running()) {
    if (in_loop_.empty() && unsent_.empty()) {
      pr.tail = false;
      planning_ = false;
    }
    return true;
  }
  const std::size_t index = e.id - 1;
  const programs::Item* item = index < pr.items.size() ? &pr.items[index] : nullptr;
  if (e.kind == core::EventKind::Done) {
    pr.done_block = std::max(pr.done_block, static_cast<std::size_t>(e.id));
    if (pr.probe && *pr.probe == e.id) {
      pr.probe.reset();
      planner_.set_position(pose_of(e.end));  // where the probe stopped
    }
  } else {
    const auto* probe = item ? std::get_if<programs::Probe>(&item->step) : nullptr;
    if (probe && pr.probe && *pr.probe == e.id && e.fail == core::FailReason::PartNotFound && !probe->error_on_miss) {
      pr.probe.reset();  // G38.3: a miss is no error; the machine stands at the target
      pr.done_block = std::max(pr.done_block, static_cast<std::size_t>(e.id));
      planner_.set_position(probe->target);
    } else {
      fail_program(item ? item->line : 0, "Failed " + std::string(fail_wording(e.fail).name));
      return true;
    }
  }
  feed_program();
  show_block(false);
  program_progress();
  return true;
}

// The program cannot go on: stop, drop what is planned, ProgEnd failed.
void Server::fail_program(int line, const std::string& why) {
  core_.request_stop();
  drop_planned(core::FailReason::Stopped);
  end_program(ProgramOutcome::Failed, line, why);
}

void Server::end_program(ProgramOutcome how, int line, const std::string& text) {
  auto& pr = program_;
  if (!pr.running()) return;
  show_block(true);
  pr.state = ProgramState::Ended;
  pr.probe.reset();
  pr.pause_at.reset();
  pr.tail = !in_loop_.empty() || !unsent_.empty();
  if (!pr.tail) planning_ = planner_.pending() > 0 || planner_.ready() > 0;
  const std::string event = pr.loaded->name + " " + outcome_name(how) + " " + std::to_string(line) + " " + text;
  log_limited(how == ProgramOutcome::Ok ? spdlog::level::info : spdlog::level::warn, "program", "program " + event);
  broadcast(format_event("ProgEnd", event));
}

// The block executing now, at most every kBlockEvery (always when `now_or_never`, before a
// ProgPause or ProgEnd, if it changed). Called on every Done of the program and by the
// position report timer (which catches a block whose Block was held back by the rate).
void Server::show_block(bool now_or_never) {
  auto& pr = program_;
  if (!pr.running()) return;
  const auto& snap = core_.snapshot();
  // The segment in the loop's hand; before the loop took the first, the first one sent.
  std::size_t block = pr.shown_block;
  if (snap.path_running && snap.path_id >= 1 && snap.path_id <= pr.items.size()) block = snap.path_id;
  else if (!in_loop_.empty() && in_loop_.front().first <= pr.items.size()) block = in_loop_.front().first;
  if (now_or_never && pr.done_block > block) block = pr.done_block;
  if (block == pr.shown_block || block == 0) return;
  const auto now = snap.time;
  if (!now_or_never && now - pr.shown_at < kBlockEvery) return;
  pr.shown_block = block;
  pr.shown_at = now;
  broadcast(format_event("Block", pr.loaded->name + " " + std::to_string(pr.items[block - 1].line) + " " +
                                      std::to_string(block) + "/" + std::to_string(pr.items.size())));
}

}  // namespace imess::net
