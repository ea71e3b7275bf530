// Server: the io thread's side of messd — accepts clients on TCP, turns their lines into
// replies or motion-loop commands, and turns motion-loop events into broadcasts.
#pragma once
#include <boost/asio.hpp>
#include <spdlog/spdlog.h>
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <variant>
#include <string>
#include <string_view>
#include <utility>

#include "imess/core/event_fd.hpp"
#include "imess/core/loop_runner.hpp"
#include "imess/core/motion_core.hpp"
#include "imess/journal/journal.hpp"
#include "imess/net/control.hpp"
#include "imess/net/host_list.hpp"
#include "imess/net/ipp_server.hpp"
#include "imess/net/log_limiter.hpp"
#include "imess/net/part_frames.hpp"
#include "imess/net/program_run.hpp"
#include "imess/net/session.hpp"
#include "imess/planner/planner.hpp"
#include "imess/protocol/commands.hpp"
#include "imess/protocol/verb_spec.hpp"

namespace imess::net {

// Who may connect, control and force a take-over; slots kept for controllers; when a
// client counts as gone (docs/configuration.md, "control").
struct ControlConfig {
  HostList hosts = loopback_hosts();          // may take control
  HostList observe_hosts = any_host();        // may connect and observe (control hosts may too)
  HostList force_hosts = loopback_hosts();    // may Take force (must also be in hosts)
  std::size_t reserved_slots = 4;             // of max_clients, only for hosts in `hosts`
  double idle_drop_s = 300;                   // silent this long while controlling or watching: dropped
  double no_command_drop_s = 300;             // from a control host, no command this long after connecting: dropped (0: never)
  double write_stall_s = 10;                  // one write unfinished this long (not reading): dropped
  std::uint32_t max_in_flight = 32;           // per client, commands waiting in the motion loop's ring
};

struct ServerConfig {
  std::string listen = "0.0.0.0";
  std::uint16_t port = 1066;      // 0: any free port (tests)
  double report_hz = 10;          // CurrCor rate, only when the position changed
  // false: CurrCor only on connect, no rate timer — for the golden transcripts, which run the
  // machine in virtual time and must not depend on a wall-clock timer (tests/golden/README.md).
  bool stream_position = true;
  std::size_t max_clients = 100;
  std::size_t max_queue_bytes = 1 << 20;  // per client; beyond it a non-reading client is dropped
  bool log_traffic = false;       // -dc
  bool log_motion = false;        // -dm
  bool log_status = false;        // -dt
  bool log_timing = false;        // -p
  bool beep = true;               // BEL on the console for every point (when it is a terminal)
  // Events are drained when the motion loop wakes the io thread; this timer only catches a
  // wake-up that never came (and is the only drain when the server has no EventFd).
  double event_backstop_ms = 50;
  double reply_timeout_s = 2;     // a reply slot unanswered this long (answer lost) becomes Err 500
  ControlConfig control;
  std::string version = "0.1.0";
  double period_us = 1000;          // the motion loop's period (Get Period)
  std::string backend = "unknown";  // the backend type (Get Backend): one word
  ProgramConfig programs;           // the programs folder and how program words map to this machine
  IppConfig ippdme;                 // the I++ DME server (TCP 1294) and its tools
  std::string frames_file;          // the part frames' store (JSON); empty: kept for this run only
  std::array<double, 3> probe_offset{};  // ProbeOffX/Y/Z: added to every measured point (mm)
};

// Opens, binds and listens on listen:port (0: any free port); returns the port. Throws
// std::runtime_error naming the address (with `busy_hint` when the port is taken); `what`
// names the listener (" for I++ DME").
std::uint16_t open_listener(boost::asio::ip::tcp::acceptor& acceptor, const std::string& listen, std::uint16_t port,
                            std::string_view what, std::string_view busy_hint);

// A queued command on the wire; after an unfinished Probe it waits in the server, unplanned
// (its start is the Probe's end, known only after the hit).
using QueuedCommand = std::variant<protocol::MoveTo, protocol::ArcTo, protocol::Dwell, protocol::Probe, protocol::SetOut>;

class Server {
 public:
  // runner may be null (no timing statistics: Stats then reports zeros). Every measured point
  // is appended to `journal` before any client is sent it. wake: the EventFd the core
  // notifies (core.set_event_signal), or null: events are then drained by the backstop timer.
  Server(boost::asio::io_context& io, ServerConfig config, core::MotionCore& core, core::LoopRunner* runner,
         journal::Journal& journal, core::EventFd* wake = nullptr);
  // Binds and starts accepting; throws std::runtime_error naming the address on failure.
  void start();
  void stop();
  std::uint16_t port() const { return port_; }
  std::size_t clients() const { return sessions_.size(); }
  // The I++ DME listener's port (0: off: the configuration turned it off, or the machine has
  // no linear X Y Z) and whether its one client is connected.
  std::uint16_t ipp_port() const { return ipp_ ? ipp_->port() : 0; }
  bool ipp_connected() const { return ipp_ && ipp_->connected(); }
  // The I++ move reports (OnMoveReportE): the report timer calls it; the golden harness,
  // whose position stream is off, every motion cycle in virtual time.
  void move_reports() {
    to_ipp("MoveReport", [&] { ipp_->tick(); });
  }

 private:
  // server.cpp
  void accept();
  void admit(boost::asio::ip::tcp::socket socket);
  void refuse(boost::asio::ip::tcp::socket& socket, std::string line);
  void closed(Session& s);
  void broadcast(const std::string& line);
  void send(Session& s, std::string line);    // an event line for one client
  void reply(Session& s, std::uint32_t slot, std::string lines);  // fills a reply slot
  void schedule(boost::asio::steady_timer& t, std::chrono::microseconds every, void (Server::*fn)());
  void rearm(boost::asio::steady_timer& t, std::chrono::microseconds every, void (Server::*fn)());
  // Logs through the rate limiter: at most 5 lines a second per message class.
  void log_limited(spdlog::level::level_enum level, std::string_view message_class, const std::string& text);
  // server_control.cpp
  bool allowed(Session& s, const protocol::Command& cmd, std::uint32_t slot);
  void take(Session& s, std::uint32_t slot, const protocol::Take& t);
  void release(Session& s, std::uint32_t slot);
  // release + stop + announce; `gone`: the client left (disconnected, dropped), so a program
  // it ran detached goes on.
  void lose_control(Session& s, std::string_view why, bool gone);
  void announce_control();
  Controller controller(Session& s) const;
  // Stops whatever moves, for the dead-man, Release, disconnect and take-over. The one
  // place a stop is made for control reasons (the motion core's stop lane replaces its body).
  // `who` names the stop in a running program's ProgEnd (StopMv, Abort, disconnected ...).
  void stop_machine(std::string_view who = "StopMv");
  // liveness.cpp
  // One timer at the earliest deadline that exists — the owner's dead-man, the journal's
  // fdatasync — and none at all when nothing waits.
  void arm_housekeeping();
  void housekeeping();
  std::optional<std::chrono::steady_clock::time_point> watch_deadline() const;
  void check_watch();     // the owner's dead-man, at its deadline
  void check_clients();   // every 250 ms: stalled writers, silent controllers
  void drop(Session& s, std::string_view why);
  // dispatch.cpp
  void on_line(Session& s, const protocol::FramedLine& line);
  void on_command(Session& s, std::uint32_t slot, const protocol::Command& cmd);
  bool to_core(Session& s, std::uint32_t slot, core::Command c);
  void stop_request(Session& s, std::uint32_t slot);
  void hello(Session& s, std::uint32_t slot, const protocol::Hello& c);
  void help(Session& s, std::uint32_t slot);
  void press_key(Session& s, std::uint32_t slot, const std::string& name);
  void get_param(Session& s, std::uint32_t slot, const protocol::Get& c);
  void set_param(Session& s, std::uint32_t slot, const protocol::Set& c);
  void qualify(Session& s, std::uint32_t slot, const protocol::Qualify& c);
  std::string status_line();
  // stats.cpp: the motion loop's timing (Stats, Stats Reset, Stats Interval, Stats Hist)
  void stats(Session& s, std::uint32_t slot, const protocol::Stats& c);
  void reply_when_restarted(std::weak_ptr<Session> s, std::uint32_t slot, int waited);
  std::string stats_line();
  // hits.cpp, replay.cpp
  void send_hit(const core::Event& e);
  // frames.cpp: part frames on the wire
  bool frames_usable(Session& s, std::uint32_t slot, std::string_view verb);
  const metrology::Frame* frame_named(Session& s, std::uint32_t slot, std::string_view verb, std::string& name);
  void list_frames(Session& s, std::uint32_t slot);
  void show_frame(Session& s, std::uint32_t slot, std::string name);
  void part_pos(Session& s, std::uint32_t slot, std::string name);
  void use_frame(Session& s, std::uint32_t slot, std::string name);
  void set_frame(Session& s, std::uint32_t slot, const protocol::SetFrame& c);
  void align(Session& s, std::uint32_t slot, const protocol::Align& c);
  void del_frame(Session& s, std::uint32_t slot, const std::string& name);
  void store_frame(Session& s, std::uint32_t slot, std::string_view verb, const std::string& name,
                   const metrology::Frame& frame, std::string_view extra);
  // Stores and activates (without an answer or event); returns why the file was not written.
  std::string keep_frame(const std::string& name, const metrology::Frame& frame);
  void frame_changed();  // the Frame event, and the I++ DME session's PartCsy
  void send_part_point(const protocol::HitMsg& hit);
  void on_replay(Session& s, std::uint32_t slot, std::uint64_t from);
  // queue.cpp: queued moves — the planner on the io thread, the segment ring's producer
  void queue_command(Session& s, std::uint32_t slot, const QueuedCommand& c);
  planner::AppendResult plan(const QueuedCommand& c);  // appended to planner_ from its position
  void queue_status(Session& s, std::uint32_t slot);
  // The configured outputs (core config): by name, their names for a message, Outputs.
  const core::OutputSettings* find_output(std::string_view name) const noexcept;
  std::string output_names() const;
  void outputs_status(Session& s, std::uint32_t slot);
  // probe.cpp: the Probe cycle's requests, the commands held behind a running Probe
  planner::AppendResult plan_probe(const protocol::Probe& c);
  planner::AppendResult check_held(const QueuedCommand& c) const;  // what can be checked before the start is known
  void plan_held(const core::AxisVec& from);  // after the Probe's Done: plan what waited, from where it ended
  void fail_held(core::FailReason why);
  bool plan_from_here(std::string& why);  // the planner starts where the machine stands
  void feed_segments();                   // final segments into the ring while it has room
  void schedule_flush_check();            // after the lines that arrived together
  void flush_check();                     // flush when the loop holds too little motion
  void on_segment_end(const core::Event& e);  // Done / Failed
  void drop_planned(core::FailReason why);    // fail what the loop has not received, plan anew
  // programs.cpp: the programs folder, Load / Upload / Run / Abort / Program, running one
  bool check_program_text(const LoadedProgram& p, const planner::Pose& start, std::vector<programs::Item>& items,
                          programs::Check& check, std::string& error) const;
  bool program_busy(Session& s, std::uint32_t slot, std::string_view verb);  // answers Err 202 while one runs
  void list_programs(Session& s, std::uint32_t slot);
  void load_program(Session& s, std::uint32_t slot, const std::string& name);
  void finish_load(Session& s, std::uint32_t slot, std::string_view verb, const std::string& name, std::string text);
  void begin_upload(Session& s, std::uint32_t slot, const std::string& name);
  void upload_line(Session& s, const protocol::FramedLine& line);
  void run_program(Session& s, std::uint32_t slot, bool detached);
  void abort_program(Session& s, std::uint32_t slot);
  void program_status(Session& s, std::uint32_t slot);
  void resume_program();
  void feed_program();
  void program_progress();
  bool program_segment_end(const core::Event& e);
  void fail_program(int line, const std::string& why);
  void end_program(ProgramOutcome how, int line, const std::string& text);
  void show_block(bool now_or_never);
  // axes.cpp: the machine's axes on the wire
  const hal::AxisLayout& layout() const noexcept;
  std::string no_axis_text(char letter) const;
  bool machine_vector(Session& s, std::uint32_t slot, const protocol::Xyz& p, core::AxisVec& out, unsigned& given);
  bool axes_known(Session& s, std::uint32_t slot, const protocol::PathWords& w);
  // The named words of a queued command (nullptr for Dwell); a pose from start with every
  // axis the words name replaced.
  static const protocol::PathWords* words_of(const QueuedCommand& c) noexcept;
  planner::Pose target_of(const protocol::PathWords& w, const planner::Pose& start) const noexcept;
  planner::Pose pose_of(const core::AxisVec& v) const noexcept;  // the machine's axes of v as a planner pose
  void jog_axes(Session& s, std::uint32_t slot, const protocol::JogAx& c);
  std::string ax_pos_line() const;
  std::string machine_help_line(const protocol::VerbSpec& v) const;
  // events.cpp
  void wait_for_events();  // re-arms the wait on the EventFd
  void pump_events();
  void backstop_events();  // the slow timer: counts the events only it found
  // position_stream.cpp
  struct PositionLines {
    std::shared_ptr<const std::string> curr_cor, ax_pos;  // ax_pos: only when the axes are not X Y Z
  };
  PositionLines position_lines() const;
  bool send_position(Session& s, const PositionLines& lines);  // what changed since s last got it
  void report_position();         // the report timer, at the fastest rate a client needs
  void report_start_of_motion();  // the first change after rest, at once (woken by the loop)
  void watch_start_of_motion();   // the loop saw the position leave a rest: poll it until it shows
  double report_timer_hz() const;
  std::string set_stream_rate(Session& s, double hz);  // the reply to Stream
  void log_periodic();

  boost::asio::io_context& io_;
  ServerConfig config_;
  core::MotionCore& core_;
  core::LoopRunner* runner_;
  journal::Journal& journal_;
  boost::asio::ip::tcp::acceptor acceptor_;
  core::EventFd* wake_;
  std::optional<boost::asio::posix::stream_descriptor> wake_wait_;  // a dup of wake_'s fd
  boost::asio::steady_timer event_timer_, housekeeping_timer_, report_timer_, log_timer_, clients_timer_, accept_timer_;
  std::optional<std::chrono::steady_clock::time_point> housekeeping_at_;  // the housekeeping timer's deadline, when armed
  std::optional<std::chrono::steady_clock::time_point> start_watch_until_;  // looking for the first printed change after a rest, until then
  std::uint64_t rest_departures_seen_ = 0;
  std::map<std::uint32_t, std::shared_ptr<Session>> sessions_;
  std::uint32_t next_id_ = 1;
  std::uint16_t port_ = 0;
  std::string last_curr_cor_;
  bool at_rest_ = false;  // the last shared report period changed no position
  std::chrono::steady_clock::time_point shared_report_due_{};  // the next ReportHz tick
  std::string last_ax_pos_;  // AxPos: only on a machine whose axes are not exactly X Y Z
  std::uint64_t points_ = 0;
  std::uint64_t woken_ = 0, backstop_found_ = 0;  // drains by wake-up / events only the backstop found
  bool running_ = false;
  Control control_;
  LogLimiter log_limiter_;
  // Queued moves (queue.cpp). unsent_: ids in the planner, not yet in the ring, in order;
  // in_loop_: ids in the ring or the loop's hand with their planned seconds.
  planner::Planner planner_;
  bool planning_ = false;  // planner_ continues the queued path (else: starts where the machine stands)
  std::deque<std::uint32_t> unsent_;
  std::deque<std::pair<std::uint32_t, double>> in_loop_;
  std::uint32_t drops_ = 0;  // the loop's queue drops known here (stamped on every segment)
  std::optional<std::uint32_t> probe_open_;  // a Probe planned whose Done has not come yet
  std::deque<QueuedCommand> held_;           // commands queued after it, unplanned
  bool flush_check_posted_ = false;
  ProgramRun program_;  // the one program loaded or running (programs.cpp)
  PartFrames frames_;   // the part frames and the active one (frames.cpp)
  // The I++ DME server: a second way in, driving this planner under this control (ipp_*.cpp).
  friend class IppServer;
  std::unique_ptr<IppServer> ipp_;
  // Every call into it from the event drain and the MESSD side: an exception there ends the I++
  // session (IppServer::guarded), never the io thread and messd with it.
  template <class F>
  void to_ipp(std::string_view what, F&& f) {
    if (ipp_) ipp_->guarded(what, std::forward<F>(f));
  }
};

}  // namespace imess::net
