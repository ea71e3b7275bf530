// IppServer: messd's I++ DME server (docs/ippdme.md, "Server") — one inspection-software
// client on TCP 1294 driving the same motion core as the MESSD clients on 1066. It reads
// lines with imess::ippdme, keeps the session, the two queues, the error state and the
// daemons, and moves the machine through the public interfaces of the services it shares
// with the MESSD front end (MotionGateway, ControlService, FrameService, ProgramRunner); the
// machine's events reach it as an observer (IppEvents), like every front end. The connection
// and transaction rules are IppTransactions'.
#pragma once
#include <boost/asio.hpp>
#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "imess/core/core_types.hpp"
#include "imess/ippdme/csy.hpp"
#include "imess/net/control.hpp"
#include "imess/net/control_service.hpp"
#include "imess/net/frame_service.hpp"
#include "imess/net/host_list.hpp"
#include "imess/net/ipp_config.hpp"
#include "imess/net/ipp_transactions.hpp"
#include "imess/net/motion_gateway.hpp"
#include "imess/net/observers.hpp"
#include "imess/net/program_runner.hpp"
#include "imess/ippdme/format.hpp"
#include "imess/ippdme/line_framer.hpp"
#include "imess/ippdme/parser.hpp"
#include "imess/ippdme/tools.hpp"
#include "imess/planner/axes.hpp"
#include "imess/planner/segment.hpp"

namespace imess::net {

// What the I++ DME front end drives and reads (all owned by net::Server).
struct IppServices {
  MotionGateway& gateway;
  ControlService& control;
  FrameService& frames;
  const ProgramRunner& programs;
  const HostList& hosts;  // control.hosts: who may connect (and so control the machine)
};

class IppServer : public IppTransactions {
 public:
  // The core's client number of the I++ session (its Home replies) and its control identity.
  static constexpr std::uint32_t kClientId = kIppSession;
  // Segment ids of the I++ session's moves: never a MESSD client's (docs/ippdme.md).
  static constexpr std::uint32_t kIdBase = 0xF0000000u;
  static bool is_own_id(std::uint32_t id) { return id >= kIdBase && id < kClientId; }

  IppServer(boost::asio::io_context& io, IppServices services, IppConfig config);
  void start(const std::string& listen);  // throws std::runtime_error naming the address

  // The machine's events, from the observer fan-out (IppEvents, ipp_events.hpp; io thread).
  void segment_end(const core::Event& e);      // Done / Failed of an own id
  void hit(const core::Event& e);              // every measured point, after the journal
  void scanned(const core::Event& e);          // a scan's point, after the journal (ipp_scan.cpp)
  void core_reply(const core::Event& e);       // the loop's answer to the session's Home
  void homed();
  void home_failed();                          // Warn HomingFailed, a fault while homing
  void dropped(core::FailReason why);          // the gateway dropped what was planned
  void tick();                                 // the move report daemon, a waiting move (report timer / harness)
  void retry();                                // a move that waited for the machine to stand (State events)
  void key(const std::string& name);           // Key <name> from the jog panel: KeyPress
  bool listening_for_keys() const { return conn_ && in_session_ && user_enabled_; }
  // The controller's active part frame changed (UseFrame, SetFrame, Align ...): PartCsy follows.
  void part_frame_changed();

 private:
  struct MoveDaemon {
    ippdme::Tag tag;
    std::optional<double> time, dis;
    std::vector<ippdme::Item> items;
    std::optional<std::chrono::nanoseconds> last_at;
    ippdme::Point3 last{};
  };

  // ipp_server.cpp: the session and control
  bool claim_control(bool at_start, std::string& why);  // the session owns the machine
  void release_control();
  void end_session(bool dropped) override;
  // ipp_commands.cpp: one command, answered at once (true) or started (false: a motion step)
  bool execute(const Pending& p) override;
  void execute_fast(const Pending& p) override;
  void get_props(const ippdme::Tag& tag, const std::vector<std::string>& paths, std::string_view cause);
  void set_props(const ippdme::Tag& tag, const std::vector<ippdme::PropertySetting>& settings, std::string_view cause);
  std::string position_payload(const std::vector<ippdme::Item>& items) const;
  void change_tool(std::string_view name);
  // ipp_motion.cpp: GoTo, PtMeas, Home through the MotionGateway
  bool take_machine(const Pending& p);
  bool start_goto(const Pending& p, const ippdme::GoTo& c);
  bool start_ptmeas(const Pending& p, const ippdme::PtMeas& c);
  bool start_home(const Pending& p);
  bool machine_faulted() const;                 // the motion core is in its fault state
  bool start_reset(const Pending& p);           // ClearAllErrors on a faulted machine: the core's Reset
  enum class Planned : unsigned char { Yes, Busy, OutOfTravel, Refused };  // Busy: the machine still moves
  Planned plan_lines(std::vector<planner::Line> lines, std::string& why);
  Planned plan_requests(const std::vector<planner::Request>& requests, std::string& why);
  // ipp_scan.cpp: the known-contour scans (ScanOnLine, ScanOnCircle, ScanOnHelix) as a scan of
  // the motion core, their points as data lines per OnScanReport
  bool start_scan(const Pending& p, const planner::ScanShape& shape, double step_mm);
  bool start_scan_line(const Pending& p, const ippdme::ScanOnLine& c);
  bool start_scan_circle(const Pending& p, const ippdme::Point3& centre, const ippdme::Point3& start,
                         const ippdme::Vector3& normal, double delta, double sfa, double step_deg, double pitch);
  void flush_scan_points();                    // the points held back, as data lines of the scan's tag
  // The unknown contours (ScanInPlaneEndIs…, ScanInCylEndIs…): the core's contour scan.
  template <class T>
  bool start_contour(const Pending& p, const T& c);
  std::optional<double> unknown_density_;      // ScanUnknownDensity's Dis: the spacing when StepW is 0
  static ippdme::ErrorCode refusal_error(Planned p);  // OutOfTravel 2500, else 0511
  void end_step(std::optional<ippdme::ErrorCode> error);
  void step_failed(ippdme::ErrorCode code);
  bool wait_for_rest();
  void step_done();
  ippdme::Point3 tip_machine() const;          // where the tip centre stands, machine X Y Z
  ippdme::Point3 tip_here() const;             // the same in the current coordinate system
  planner::Pose pose_at(const ippdme::Point3& machine_xyz) const;
  std::vector<ippdme::Value> hit_values(const core::Event& e) const;  // as OnPtMeasReport asks
  std::uint32_t next_id();

  MotionGateway& gateway_;
  ControlService& control_;
  FrameService& frames_;
  const ProgramRunner& programs_;
  bool user_enabled_ = false;
  std::vector<ippdme::Item> ptmeas_items_{ippdme::Item::X, ippdme::Item::Y, ippdme::Item::Z};
  std::vector<ippdme::Item> scan_items_ = ippdme::kDefaultScanReport;  // OnScanReport
  std::vector<ippdme::ScanPoint> scan_points_;  // the running scan's points not yet sent (< kScanPointsPerLine)
  std::optional<MoveDaemon> daemon_;
  ippdme::ToolBox tools_;
  ippdme::CsyChain csy_;
  // PartCsy as the session set it becomes the controller's frame "PartCsy"; false (nothing
  // stored) when the chain gives no usable frame.
  bool store_part_csy();
  bool own_part_csy_ = false;  // this session's SetCsyTransformation(PartCsy) is being stored
  // The motion step of the queue's front (its kind: step_).
  std::uint32_t wait_id_ = 0;              // its last segment: its Done completes the step
  std::uint32_t first_id_ = 0;             // its first segment (ids first_id_..wait_id_ are its own)
  std::uint32_t next_id_ = kIdBase;
  ippdme::Point3 approach_m_{}, normal_m_{};  // PtMeas: the approach point and the surface normal, machine
  bool hit_seen_ = false;
  ippdme::Point3 hit_tip_m_{};                 // PtMeas: the ball's centre at the touch, machine
  // PtMeas: where the probe cycle stopped (its Done), the start of the retract; between steps
  // the machine's own position is the start (the operator may have moved it).
  std::optional<planner::Pose> rest_;
};

}  // namespace imess::net
