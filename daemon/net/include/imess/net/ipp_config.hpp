// The I++ DME server's configuration (docs/configuration.md, "server.ippdme_port", "ippdme").
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace imess::net {

struct IppConfig {
  bool on = true;                 // false: no I++ listener (ippdme_port 0)
  std::uint16_t port = 1294;      // 0 with on: any free port (tests)
  // Tools as configured; empty: one tool "RefTool" with the machine's tip radius. Ranges
  // not given come from the machine (IppServer fills them).
  struct Tool {
    std::string name;
    std::optional<double> radius;
  };
  std::vector<Tool> tools;
  std::size_t max_queue_bytes = 1 << 20;  // output waiting for a client that does not read: dropped beyond
};

}  // namespace imess::net
