// The I++ DME property tests' parts (test_ippdme_properties.cpp has the rules they check):
// the machine of a configuration and its random session script (ippdme_property_script.cpp),
// and the rules judged on what the clients received (ippdme_property_rules.cpp).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "imess/core/core_types.hpp"
#include "imess/sim/scene.hpp"
#include "transcript.hpp"

namespace imess::golden::ippdme_properties {

constexpr long kRestWithinMs = 1000;  // a rest probe's wait: braking from full speed and a retract take well under this

// Whether sessions send bursts of lines beyond one read of the server (4 KiB in one write);
// messd once spliced and repeated lines then (test_ippdme_findings.cpp, the second finding).
constexpr bool kBurstsBeyondOneRead = true;
// Whether sessions queue more commands than messd takes (64) behind a move; messd once
// stopped reading the connection then, so an AbortE or a drop went unseen until the move
// ended (test_ippdme_findings.cpp, the third finding). Their Acks wait now.
constexpr bool kQueueBeyondItsLimit = true;

// What the script and the rules need of a configuration's machine.
struct Machine {
  std::string config;
  std::array<double, 3> lo{}, hi{};  // X Y Z travel
  std::array<int, 3> axis{};         // the machine's axis index of X, Y, Z
  bool referenced = false;           // soft limits hold: a MESSD jog stays within the travel
  double tip = 2;                    // the ball radius of the session's tool
  double safe_z = 0;                 // above every solid, within the travel
  hal::Vec3 centre = hal::Vec3::Zero();        // where the work is: the first box, else the travel's middle
  sim::Scene scene;
  long period_us = 1000;
};

// Whether the configuration has an I++ DME server (a machine with linear X Y Z axes).
bool has_ipp_server(const std::string& config);
Machine machine_of(const std::string& config);
// Every shipped configuration with an I++ DME server, sorted.
std::vector<std::string> ipp_configs();

// A Status of client 1 that must find the machine standing: `status_step` after the AbortE,
// EndSession or drop of `trigger_step`.
struct RestProbe {
  enum Kind { Abort, End, Drop } kind;
  int client = 0, trigger_step = 0, status_step = 0;
  std::string tag;  // the AbortE's or EndSession's
};

struct Script {
  std::vector<Entry> entries;
  std::vector<RestProbe> probes;
  std::set<int> ipp_clients;      // every I++ client that had a session
  std::set<int> refused_clients;  // second I++ clients (refused)
  std::set<int> clean_clients;    // closed only after EndSession's `%` with nothing open
  int final_client = 0;           // the new client of rule 4
  int final_status_step = 0;      // client 1's last Status
};

// A random session of `actions` actions for this machine: the same for the same seed.
Script make_script(const Machine& m, std::uint64_t seed, int actions);

// What the rules saw happen, counted: every configuration must show the main kinds.
struct Counts {
  int lines_sent = 0, accepted = 0, garbled = 0, tag_errors = 0, completed = 0, errors_seen = 0;
  int goto_done = 0, goto_limit = 0, ptmeas_points = 0, ptmeas_errors = 0, aborts_in_motion = 0;
  int error_state_refusals = 0, warnings_0504 = 0, move_reports = 0, drops = 0, drops_mid_move = 0;
  int rest_checked = 0, rest_skipped = 0, control_given_back = 0, refused_209 = 0, panel_moves_ok = 0;
  int positions_checked = 0, refused_clients = 0, final_checks = 0;
  int slow_retracts = 0, arrivals_checked = 0, report_gaps_checked = 0;
  double arrival_max_off = 0;
  long rest_max_ms = 0, retract_max_ms = 0, virtual_ms = 0;
  double travel_max_excess = 0;

  void add(const Counts& o);
  std::string text() const;
};


struct Verdict {
  std::vector<std::string> problems;  // each rule broken, "step N: …"
  Counts counts;
};

// The rules on a replay's output (`end`: the motion core after the last step, when known).
Verdict check_session(const Machine& m, const Script& script, const std::vector<Entry>& out, const std::optional<core::Snapshot>& end);

}  // namespace imess::golden::ippdme_properties
