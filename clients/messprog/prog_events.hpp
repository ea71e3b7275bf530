// The program events messd broadcasts while a program runs (docs/protocol.md: Block,
// ProgPause, ProgEnd) and the figures of its `Ok Load` reply, read from their lines.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace imess::messprog {

// `Block <name> <line> <i>/<total>`: the block (item) now executing.
struct BlockEvent {
  std::string name;
  int line = 0;
  std::size_t index = 0, total = 0;  // 1-based item index, item count
};

// `ProgPause <name> <line> M0`: an M0 was reached; the machine stands until Resume.
struct ProgPauseEvent {
  std::string name;
  int line = 0;
};

// `ProgEnd <name> ok|failed|aborted <line> <text...>`.
struct ProgEndEvent {
  enum class Outcome { Ok, Failed, Aborted } outcome = Outcome::Ok;
  std::string name;
  int line = 0;
  std::string text;  // "end", "Failed PartNotFound", "Abort", "StopMv", "disconnected"
};

// nullopt when the line is not that event or is malformed.
std::optional<BlockEvent> parse_block(std::string_view line);
std::optional<ProgPauseEvent> parse_prog_pause(std::string_view line);
std::optional<ProgEndEvent> parse_prog_end(std::string_view line);

const char* outcome_name(ProgEndEvent::Outcome outcome);  // "ok", "failed", "aborted"

// The arguments of `Ok Load <name> Lang gcode Lines 12 Blocks 10 Segments 9 Length 123.4 Time 12.3`
// (after the verb) as "gcode, 12 lines, 10 blocks, 9 segments, 123.4 mm, about 12.3 s"; words it
// does not know are kept as they are.
std::string load_summary(const std::vector<std::string>& args);

}  // namespace imess::messprog
