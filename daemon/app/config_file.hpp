// Reading a configuration file (JSON or messdrc) into memory, with one clear ConfigError for
// every way a file can be unusable: missing, a directory, unreadable, not a plain file, huge.
#pragma once
#include <string>

namespace imess::app {

// Largest configuration file read (far beyond any real one; stops /dev/zero and mistakes).
inline constexpr std::size_t kMaxConfigFileBytes = 4 * 1024 * 1024;

// The whole text of `path`; `what` names the kind of file in messages ("configuration file"),
// `flag` the option that names it ("--config").
std::string read_config_file(const std::string& path, const std::string& what, const std::string& flag);

}  // namespace imess::app
