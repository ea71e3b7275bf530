// The bridge's state file: the last seq the broker acknowledged, so a restarted bridge resumes
// where the broker's copy ends. One line of JSON, {"machine": "cmm1", "acked": 1234}, written
// to a temporary file and renamed over the old one (never half written).
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace imess::mqtt {

// The acknowledged seq in `path`; nothing when the file does not exist. Throws
// std::runtime_error naming the file when it exists but is unusable (another machine's, not
// our form): resuming from a guess could skip hits.
std::optional<std::uint64_t> load_acked(const std::string& path, const std::string& machine);
// Throws std::runtime_error naming the file when it cannot be written.
void save_acked(const std::string& path, const std::string& machine, std::uint64_t acked);

}  // namespace imess::mqtt
