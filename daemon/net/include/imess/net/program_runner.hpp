// ProgramRunner: the one program loaded or running — the programs folder, Load and Upload
// (translated and checked against this machine before anything moves), Run (items planned
// ahead of the loop through the MotionGateway, like queued moves), M0, probes, Abort's end,
// and its Block / ProgPause / ProgEnd events. Rules in docs/programs.md ("Running programs").
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "imess/net/log_limiter.hpp"
#include "imess/net/motion_gateway.hpp"
#include "imess/net/observers.hpp"
#include "imess/net/frame_service.hpp"
#include "imess/net/program_run.hpp"

namespace imess::net {

class ProgramRunner : public MotionObserver {
 public:
  using Answer = std::function<void(std::string)>;   // the reply to the request
  using Announce = std::function<void(const std::string&)>;  // an event line to every client

  ProgramRunner(MotionGateway& gateway, const ProgramConfig& config, FrameService& frames, LogLimiter& log,
                Announce announce);

  bool running() const noexcept { return program_.running(); }
  bool detached() const noexcept { return program_.detached; }
  const std::string& name() const { return program_.loaded->name; }
  // While one runs: the Err 202 for `verb` (a command that would move the machine besides it).
  bool busy(std::string_view verb, const Answer& answer) const;

  // The verbs (`client`: who asks, for the log).
  void list(const Answer& answer) const;
  void load(std::uint32_t client, const std::string& name, const Answer& answer);
  void finish_load(std::uint32_t client, std::string_view verb, const std::string& name, std::string text, const Answer& answer);
  void run(std::uint32_t client, bool detached, const Answer& answer);
  void status(const Answer& answer) const;
  void resume();  // Resume: a program waiting at its M0 goes on
  // The block executing now (rate-limited unless `now_or_never`): the report timer calls it.
  void show_block(bool now_or_never);

  // The loaded program's path as its last check (Load, Upload, Run) planned it, each planned
  // segment to `visit` (the web panel draws it). False with `error` when none is loaded or it
  // no longer passes.
  bool loaded_path(const programs::SegmentVisitor& visit, std::string& name, std::string& error) const;
  const core::AxisLayout& layout() const;

  // The observer's side: its ids, the drop (a fault fails it) and a stop (ends it aborted).
  bool owns_segment(std::uint32_t id) const override;
  void segment_end(const core::Event& e) override;
  void dropped(core::FailReason why) override;
  void stopped(std::string_view who) override;

 private:
  bool check_program_text(const LoadedProgram& p, const planner::Pose& start, std::vector<programs::Item>& items,
                          programs::Check& check, std::string& error) const;
  void feed_program();
  void store_offsets(std::size_t upto);
  void program_progress();
  bool program_segment_end(const core::Event& e);
  void fail_program(int line, const std::string& why);
  void end_program(ProgramOutcome how, int line, const std::string& text);

  MotionGateway& gateway_;
  const ProgramConfig& config_;
  FrameService& frames_;
  LogLimiter& log_;
  Announce announce_;
  ProgramRun program_;
  mutable planner::Pose checked_from_{};  // where the last check started (loaded_path plans from it)
};

}  // namespace imess::net
