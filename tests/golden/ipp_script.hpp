// Short I++ DME scripts for the golden harness: the usual start (the default simulated CMM,
// client 2 on the I++ port, StartSession) and what client 2 received, in order — shared by the
// I++ cases that replay a few lines and look at the answers (conformance, findings, hostile).
#pragma once
#include <algorithm>
#include <string>
#include <vector>

#include "golden_harness.hpp"

namespace imess::golden {

inline const std::string kIppStart = "@ config/sim-servo-card.json\n+2 ipp\n2> 00001 StartSession()\n";

// The lines the I++ client (client 2) received when `script` is replayed; `name` names the
// script in the harness's messages.
inline std::vector<std::string> ipp_session_lines(const std::string& script, const std::string& name) {
  std::vector<std::string> lines;
  for (const auto& e : replay(parse_transcript(script, name), name))
    if (e.kind == EntryKind::Receive && e.client == 2) lines.push_back(e.text);
  return lines;
}

// Where `line` is among `lines` (-1: not there).
inline long index_of(const std::vector<std::string>& lines, const std::string& line) {
  const auto it = std::find(lines.begin(), lines.end(), line);
  return it == lines.end() ? -1 : static_cast<long>(it - lines.begin());
}

}  // namespace imess::golden
