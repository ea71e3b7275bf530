// The daemon's version: what Hello, Version and `messd --version` say. One place, so the
// golden transcripts' daemon (tests/golden) answers exactly as messd does.
#pragma once

namespace imess::app {
inline constexpr const char* kVersion = "0.1.0";
}  // namespace imess::app
