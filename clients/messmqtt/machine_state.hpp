// MachineState: what imess/<machine>/state retains, folded from messd's lines — its state,
// who controls it, where it stands, the program, the last fault and the last hit. fold_line
// also says which lines are events for imess/<machine>/event (faults, warnings, program
// pauses and ends, limits, homing, qualification).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace imess::mqtt {

struct MachineState {
  bool messd = false;              // the bridge is connected to messd
  std::string state = "unknown";   // State: free idle jog move retract home fault stopping
  std::string control = "none";    // "name@host" of the client in control, or "none"
  std::optional<std::array<double, 3>> position;  // CurrCor, mm
  struct Program {
    std::string name = "none";
    std::string state = "none";    // none loaded running paused ended
    long line = 0;
    std::string block;             // "<i>/<total>"
    std::string result;            // after ProgEnd: ok failed aborted, and its text
  } program;
  struct Fault {
    std::string name, text, time;
  };
  std::optional<Fault> last_fault;
  struct LastHit {
    std::uint64_t seq = 0;
    std::array<double, 3> p{};
    std::string time;
  };
  std::optional<LastHit> last_hit;
};

struct Folded {
  bool changed = false;        // the retained state changed
  bool only_position = false;  // ... and only its position (rate-limited harder)
  std::optional<nlohmann::json> event;  // an event payload's fields (type and its own), if any
};

// Folds one line from messd; `now` is the wall time for faults and hits (ISO 8601, UTC).
Folded fold_line(MachineState& s, std::string_view line, const std::string& now);

}  // namespace imess::mqtt
