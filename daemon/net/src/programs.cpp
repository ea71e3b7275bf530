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
#include "imess/net/program_runner.hpp"
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

}  // namespace

// A name in the programs folder: one file name, printable, no path.
std::string program_name_problem(const std::string& name) {
  if (name.size() > 255) return "a name of at most 255 characters";
  for (char c : name)
    if (c == '/' || c == '\\' || static_cast<unsigned char>(c) < 33 || static_cast<unsigned char>(c) > 126)
      return "a file name without '/', '\\', blanks or control characters";
  if (name.find("..") != std::string::npos || name.front() == '.') return "a file name not starting with '.' and without '..'";
  if (!programs::language_of(name))
    return std::string("a name ending in one of ") + programs::kExtensions + " (it gives the language)";
  return {};
}

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

metrology::Frame frame_of_offset_write(const programs::OffsetWrite& w, const hal::AxisLayout& layout) {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  for (int c = 0; c < 3; ++c)
    if (const int a = layout.cartesian_axis(c); a >= 0) origin[c] = w.origin[static_cast<std::size_t>(a)];
  return metrology::Frame(Eigen::Matrix3d::Identity(), origin);
}

bool offset_writes_storable(const std::vector<programs::OffsetWrite>& writes, const hal::AxisLayout& layout,
                            std::string& error) {
  for (const auto& w : writes) {
    const Eigen::Vector3d origin = frame_of_offset_write(w, layout).translation();
    if (origin.cwiseAbs().maxCoeff() <= kMaxFrameOrigin) continue;
    error = "line " + std::to_string(w.line) + ":1: " + programs::kind_name(programs::ErrorKind::BadValue) + ": found G10 setting " +
            std::string(programs::kWorkOffsetNames[static_cast<std::size_t>(w.offset)]) + "'s origin " +
            std::to_string(origin.cwiseAbs().maxCoeff()) + " mm from the machine's zero, accepted origins within " +
            std::to_string(static_cast<long>(kMaxFrameOrigin)) + " mm (as SetFrame)";
    return false;
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

ProgramRunner::ProgramRunner(MotionGateway& gateway, const ProgramConfig& config, FrameService& frames, LogLimiter& log,
                             Announce announce)
    : gateway_(gateway), config_(config), frames_(frames), log_(log), announce_(std::move(announce)) {}

bool ProgramRunner::owns_segment(std::uint32_t) const { return program_.running() || program_.tail; }

void ProgramRunner::segment_end(const core::Event& e) { program_segment_end(e); }

void ProgramRunner::dropped(core::FailReason why) {
  // A limit, a fault or an unexpected touch dropped the loop's queue: the program failed
  // (a stop ends it as aborted, in stopped()).
  if (program_.running() && why != core::FailReason::Stopped) {
    const std::size_t block = std::max(program_.shown_block, program_.done_block + 1);
    const int line = block >= 1 && block <= program_.items.size() ? program_.items[block - 1].line : 0;
    end_program(ProgramOutcome::Failed, line, "Failed " + std::string(fail_wording(why).name));
  }
}

void ProgramRunner::stopped(std::string_view who) {
  if (program_.running()) end_program(ProgramOutcome::Aborted, program_.shown_block > 0 ? program_.items[program_.shown_block - 1].line : 0, std::string(who));
}

// Translates and checks the program from `start`; the items of the run in `items`.
bool ProgramRunner::check_program_text(const LoadedProgram& p, const planner::Pose& start, std::vector<programs::Item>& items,
                                programs::Check& check, std::string& error) const {
  checked_from_ = start;
  return check_program_for({config_, gateway_.config(), gateway_.machine(), gateway_.options(), &frames_.frames()}, p, start, items,
                           check, error);
}

bool ProgramRunner::loaded_path(const programs::SegmentVisitor& visit, std::string& name, std::string& error) const {
  if (!program_.loaded) {
    error = "no program loaded; Load or Upload one first";
    return false;
  }
  name = program_.loaded->name;
  std::vector<programs::Item> items;
  programs::Check check;
  return check_program_for({config_, gateway_.config(), gateway_.machine(), gateway_.options(), &frames_.frames()},
                           *program_.loaded, checked_from_, items, check, error, visit);
}

const core::AxisLayout& ProgramRunner::layout() const { return gateway_.config().layout; }

bool ProgramRunner::busy(std::string_view verb, const Answer& answer) const {
  if (!program_.running()) return false;
  answer(format_err(ErrorCode::Busy, std::string(verb) + ": program " + program_.loaded->name +
                                                 " is running; Pause, Abort or wait for its ProgEnd"));
  return true;
}

void ProgramRunner::list(const Answer& answer) const {
  const std::string& folder = config_.folder;
  if (folder.empty()) {
    answer(format_ok("Programs"));
    return;
  }
  std::vector<std::string> names;
  std::error_code ec;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (it->is_regular_file(ec) && program_name_problem(name).empty()) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  std::string line;
  for (const auto& n : names) line += (line.empty() ? "" : " ") + n;
  answer(format_ok("Programs", line));
}

void ProgramRunner::load(std::uint32_t client, const std::string& name, const Answer& answer) {
  if (busy("Load", answer)) return;
  if (auto why = program_name_problem(name); !why.empty()) {
    answer(format_err(ErrorCode::BadValue, "Load " + name + ": expected " + why));
    return;
  }
  const std::string& folder = config_.folder;
  if (folder.empty()) {
    answer(format_err(ErrorCode::BadValue, "Load " + name +
                                                       ": no programs folder is configured (programs.folder); Upload sends a program over the connection"));
    return;
  }
  const auto path = std::filesystem::path(folder) / name;
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || !std::filesystem::is_regular_file(path, ec)) {
    answer(format_err(ErrorCode::BadValue, "Load " + name + ": no such program in the programs folder; Programs lists them"));
    return;
  }
  // A symbolic link may point anywhere; only a file inside the folder is a program (an error
  // message quotes what it read, so no other file of the controller is shown to a client).
  const auto real = std::filesystem::canonical(path, ec);
  const auto root = std::filesystem::canonical(folder, ec);
  const auto rel = real.lexically_relative(root);
  if (ec || rel.empty() || *rel.begin() == "..") {
    answer(format_err(ErrorCode::BadValue, "Load " + name + ": the file lies outside the programs folder (a link); accepted: files in the folder"));
    return;
  }
  if (size > config_.max_bytes) {
    answer(format_err(ErrorCode::BadProgram, "Load " + name + ": " + std::to_string(size) + " bytes; accepted up to " +
                                                         std::to_string(config_.max_bytes)));
    return;
  }
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) {
    answer(format_err(ErrorCode::BadValue, "Load " + name + ": the file could not be read"));
    return;
  }
  finish_load(client, "Load", name, std::move(text), answer);
}

// Load and the end of an Upload: translated and checked from where the machine stands.
void ProgramRunner::finish_load(std::uint32_t client, std::string_view verb, const std::string& name, std::string text,
                                const Answer& answer) {
  if (busy(verb, answer)) return;
  LoadedProgram p{name, *programs::language_of(name), std::move(text), {}};
  std::vector<programs::Item> items;
  std::string error;
  const auto& snap = gateway_.snapshot();
  if (!check_program_text(p, gateway_.pose_of(snap.position), items, p.check, error)) {
    answer(format_err(ErrorCode::BadProgram, std::string(verb) + " " + name + ": " + error));
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
  log_limited(log_, spdlog::level::info, "program", "client " + std::to_string(client) + " loaded program " + summary);
  answer(format_ok("Load", summary));
}

void ProgramRunner::run(std::uint32_t client, bool detached, const Answer& answer) {
  if (busy("Run", answer)) return;
  if (!program_.loaded) {
    answer(format_err(ErrorCode::BadValue, "Run: no program loaded; Load or Upload one first"));
    return;
  }
  const auto& snap = gateway_.snapshot();
  if ((snap.mode != core::Mode::Idle && snap.mode != core::Mode::Free) || gateway_.planning() || gateway_.loop_holds_segments() || program_.tail) {
    answer(format_err(ErrorCode::Busy, "Run: the machine is busy (State " + std::string(mode_name(snap.mode)) +
                                                   (snap.mode == core::Mode::Fault
                                                        ? "); clear the fault with Reset first"
                                                        : "); run when it stands and the queue is empty, or StopMv")));
    return;
  }
  const planner::Pose here = gateway_.pose_of(snap.position);
  std::vector<programs::Item> items;
  std::string error;
  if (!check_program_text(*program_.loaded, here, items, program_.loaded->check, error)) {
    answer(format_err(ErrorCode::BadProgram, "Run " + program_.loaded->name + ": from where the machine stands: " + error));
    return;
  }
  gateway_.start_at(here);
  gateway_.set_planning(true);
  program_.items = std::move(items);
  program_.next = 0;
  program_.next_write = 0;
  program_.detached = detached;
  program_.feeding_done = false;
  program_.probe.reset();
  program_.pause_at.reset();
  program_.shown_block = 0;
  program_.done_block = 0;
  program_.state = ProgramState::Running;
  log_limited(log_, spdlog::level::info, "program", "client " + std::to_string(client) + " runs program " + program_.loaded->name +
                                                  (detached ? " detached" : ""));
  answer(format_ok("Run", program_.loaded->name));
  feed_program();
  gateway_.feed_segments();
  show_block(false);
  program_progress();
  gateway_.schedule_flush_check();
}

void ProgramRunner::status(const Answer& answer) const {
  if (!program_.loaded) {
    answer(format_ok("Program", "none none Line 0 Block 0/0"));
    return;
  }
  const std::size_t block = program_.shown_block;
  const std::size_t total = program_.running() || program_.state == ProgramState::Ended ? program_.items.size()
                                                                                         : program_.loaded->check.blocks;
  const int line = block > 0 && block <= program_.items.size() ? program_.items[block - 1].line : 0;
  const bool held = program_.state == ProgramState::Running && gateway_.snapshot().path_held;
  answer(format_ok("Program", program_.loaded->name + " " + (held ? "paused" : state_name(program_.state)) +
                                          " Line " + std::to_string(line) + " Block " + std::to_string(block) + "/" +
                                          std::to_string(total)));
}

// Resume: a program waiting at its M0 goes on (the feed hold, if any, is ended by the loop).
void ProgramRunner::resume() {
  if (program_.state != ProgramState::Paused) return;
  program_.state = ProgramState::Running;
  program_.pause_at.reset();
  feed_program();
  gateway_.feed_segments();
  show_block(false);
  program_progress();
  gateway_.schedule_flush_check();
}

// Items into the planner while the loop holds less than kPlanAhead of them; never past a
// probe whose end has not come (the rest starts where it ended) or an M0.
void ProgramRunner::feed_program() {
  auto& pr = program_;
  while (pr.state == ProgramState::Running && !pr.feeding_done && !pr.probe && !pr.pause_at &&
         gateway_.ids_queued() < kPlanAhead) {
    const std::size_t i = pr.next;
    store_offsets(i);
    if (i >= pr.items.size() || std::holds_alternative<programs::End>(pr.items[i].step)) {
      store_offsets(pr.items.size());
      pr.feeding_done = true;
      gateway_.flush();
      break;
    }
    const programs::Item& item = pr.items[i];
    ++pr.next;
    if (std::holds_alternative<programs::Pause>(item.step)) {
      pr.pause_at = i;
      gateway_.flush();
      break;
    }
    const auto req = programs::request_of(item, programs::item_id(i), gateway_.planned_end(), gateway_.machine());
    if (!req) continue;
    if (const auto res = gateway_.append(*req); !res.ok()) {  // the check passed from the start: only after a probe
      const std::string why = planner::describe(res, gateway_.machine());
      fail_program(item.line, "refused " + why.substr(why.find(": ") + 2));
      return;
    }
    if (std::holds_alternative<programs::Probe>(item.step)) {
      pr.probe = programs::item_id(i);
      gateway_.flush();  // the machine stops at the hit: the probe ends at rest
    }
  }
}

// The program's G10 writes before item `upto` into the part frames G54 ... G59.3 (without
// making one active): a run writes them as planning passes their lines.
void ProgramRunner::store_offsets(std::size_t upto) {
  auto& pr = program_;
  const auto& writes = pr.loaded->check.offset_writes;
  for (; pr.next_write < writes.size() && writes[pr.next_write].before_item <= upto; ++pr.next_write) {
    const auto& w = writes[pr.next_write];
    const std::string name(programs::kWorkOffsetNames[static_cast<std::size_t>(w.offset)]);
    const std::string save_error = frames_.store(name, frame_of_offset_write(w, gateway_.config().layout));
    log_limited(log_, spdlog::level::info, "program", "program " + pr.loaded->name + " line " + std::to_string(w.line) +
                                                          " wrote part frame " + name + (save_error.empty() ? "" : " (for this run only)"));
  }
}

// After every step of the run: an M0 reached (everything before it done), or the end.
void ProgramRunner::program_progress() {
  auto& pr = program_;
  if (!pr.running()) return;
  const bool empty = gateway_.ids_queued() == 0 && !gateway_.planner_holds();
  if (!empty || pr.probe) return;
  if (pr.pause_at && pr.state == ProgramState::Running) {
    pr.state = ProgramState::Paused;
    show_block(true);
    pr.shown_block = *pr.pause_at + 1;  // Program names the M0 while it waits there
    const auto& item = pr.items[*pr.pause_at];
    const auto* pause = std::get_if<programs::Pause>(&item.step);
    announce_(format_event("ProgPause", pr.loaded->name + " " + std::to_string(item.line) + " " + (pause ? pause->reason : "M0")));
    return;
  }
  if (pr.feeding_done) {
    const int line = pr.next < pr.items.size() ? pr.items[pr.next].line : pr.items.empty() ? 0 : pr.items.back().line;
    end_program(ProgramOutcome::Ok, line, "end");
  }
}

// A Done or Failed of the program's ids (true), or not the program's (false).
bool ProgramRunner::program_segment_end(const core::Event& e) {
  auto& pr = program_;
  if (!pr.running() && !pr.tail) return false;
  // No queue of a client can start while a program runs or its last segments drain, so every
  // id the loop reports now is the program's.
  if (!pr.running()) {
    if (gateway_.ids_queued() == 0) {
      pr.tail = false;
      gateway_.set_planning(false);
    }
    return true;
  }
  const std::size_t index = e.id - 1;
  const programs::Item* item = index < pr.items.size() ? &pr.items[index] : nullptr;
  if (e.kind == core::EventKind::Done) {
    pr.done_block = std::max(pr.done_block, static_cast<std::size_t>(e.id));
    if (pr.probe && *pr.probe == e.id) {
      pr.probe.reset();
      gateway_.start_at(gateway_.pose_of(e.end));  // where the probe stopped
    }
  } else {
    const auto* probe = item ? std::get_if<programs::Probe>(&item->step) : nullptr;
    if (probe && pr.probe && *pr.probe == e.id && e.fail == core::FailReason::PartNotFound && !probe->error_on_miss) {
      pr.probe.reset();  // G38.3: a miss is no error; the machine stands at the target
      pr.done_block = std::max(pr.done_block, static_cast<std::size_t>(e.id));
      gateway_.start_at(probe->target);
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
void ProgramRunner::fail_program(int line, const std::string& why) {
  gateway_.abandon_plan();
  end_program(ProgramOutcome::Failed, line, why);
}

void ProgramRunner::end_program(ProgramOutcome how, int line, const std::string& text) {
  auto& pr = program_;
  if (!pr.running()) return;
  show_block(true);
  pr.state = ProgramState::Ended;
  pr.probe.reset();
  pr.pause_at.reset();
  pr.tail = gateway_.ids_queued() > 0;
  if (!pr.tail) gateway_.set_planning(gateway_.planner_holds());
  const std::string event = pr.loaded->name + " " + outcome_name(how) + " " + std::to_string(line) + " " + text;
  log_limited(log_, how == ProgramOutcome::Ok ? spdlog::level::info : spdlog::level::warn, "program", "program " + event);
  announce_(format_event("ProgEnd", event));
}

// The block executing now, at most every kBlockEvery (always when `now_or_never`, before a
// ProgPause or ProgEnd, if it changed). Called on every Done of the program and by the
// position report timer (which catches a block whose Block was held back by the rate).
void ProgramRunner::show_block(bool now_or_never) {
  auto& pr = program_;
  if (!pr.running()) return;
  const auto& snap = gateway_.snapshot();
  // The segment in the loop's hand; before the loop took the first, the first one sent.
  std::size_t block = pr.shown_block;
  if (snap.path_running && snap.path_id >= 1 && snap.path_id <= pr.items.size()) block = snap.path_id;
  else if (const auto first = gateway_.first_in_loop(); first && *first <= pr.items.size()) block = *first;
  if (now_or_never && pr.done_block > block) block = pr.done_block;
  if (block == pr.shown_block || block == 0) return;
  const auto now = snap.time;
  if (!now_or_never && now - pr.shown_at < kBlockEvery) return;
  pr.shown_block = block;
  pr.shown_at = now;
  announce_(format_event("Block", pr.loaded->name + " " + std::to_string(pr.items[block - 1].line) + " " +
                                      std::to_string(block) + "/" + std::to_string(pr.items.size())));
}

}  // namespace imess::net
