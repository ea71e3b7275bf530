// Which shipped configurations the tests run: config/sim-*.json drive a simulated machine;
// every other file in config/ drives real hardware (config/servo-card.json: a card on
// /dev/ttyIMESS0), so it is only loaded and checked to refuse to start without its device.
#pragma once
#include <filesystem>
#include <string>

namespace imess::test {
inline bool simulated_config(const std::filesystem::path& file) { return file.filename().string().rfind("sim-", 0) == 0; }
}  // namespace imess::test
