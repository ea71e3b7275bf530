// Command-line parsing for messd.
#include "cli.hpp"

#include <boost/asio/ip/address.hpp>
#include <stdexcept>
#include <string_view>

#include "imess/protocol/numbers.hpp"

namespace imess::app {

const char* usage_text() {
  return "usage: messd [--config FILE] [--rc FILE] [--port N] [--listen ADDR] [--journal DIR] [--programs DIR]\n"
         "             [--frames FILE] [--ippdme-port N] [--http-port N] [--device TTY] [--home] [--no-rt] [-dc] [-dm] [-dt] [-p] [-r]\n"
         "             [-v] [-h]\n"
         "  --config FILE  JSON configuration (default: the built-in simulated CMM)\n"
         "  --rc FILE      1996 messdrc (SpeedLevel, TipReversed, TipRadius); default ./messdrc if present\n"
         "  --port N       TCP port (default 1066; 0 = any free port, printed at start)\n"
         "  --ippdme-port N  I++ DME port (default 1294; 0 = off; with --port 0 and no --ippdme-port:\n"
         "                 any free port, printed at start)\n"
         "  --http-port N  the web panel's HTTP and WebSocket port (default 8080; 0 = off; with --port 0\n"
         "                 and no --http-port: any free port, printed at start)\n"
         "  --listen ADDR  address to listen on (default 0.0.0.0, all interfaces: others may observe and\n"
         "                 stop; only control.hosts, by default loopback, may move the machine)\n"
         "  --journal DIR  the hit journal (default: $STATE_DIRECTORY/journal under systemd, else\n"
         "                 ./messd-journal); created if missing, must be writable\n"
         "  --programs DIR the programs folder Load reads (overrides programs.folder)\n"
         "  --frames FILE  the part frames' store (default: $STATE_DIRECTORY/frames.json under systemd,\n"
         "                 else ./messd-frames.json); written when a frame is stored\n"
         "  --device TTY   the servo card's serial device (backend \"servo-card\"; overrides backend.device)\n"
         "  --home         run the reference search at start\n"
         "  --no-rt        do not ask for SCHED_FIFO and mlockall\n"
         "  -dc            echo all socket traffic\n"
         "  -dm            motion commands and measured coordinates in detail\n"
         "  -dt            controller status bits every 5 s\n"
         "  -p             motion-loop timing every 5 s\n"
         "  -r             force a controller reboot (reload firmware and parameters)\n"
         "  -v, --version  version\n"
         "  -h, --help     this text\n";
}

CliOptions parse_cli(int argc, char** argv) {
  CliOptions o;
  for (int i = 1; i < argc; ++i) {
    std::string_view a = argv[i];
    auto value = [&](const char* what) -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(std::string(a) + " needs " + what);
      if (argv[i + 1][0] == '\0') throw std::invalid_argument(std::string(a) + " needs " + what + ", got an empty value");
      return argv[++i];
    };
    if (a == "--config") o.config = value("a file name");
    else if (a == "--rc") o.rc = value("a file name");
    else if (a == "--journal") o.journal = value("a directory for the hit journal");
    else if (a == "--programs") o.programs = value("a directory of programs");
    else if (a == "--frames") o.frames = value("a file for the part frames");
    else if (a == "--device") o.device = value("a serial device such as /dev/ttyUSB0");
    else if (a == "--listen") {
      auto text = value("an address such as 0.0.0.0 or 127.0.0.1");
      boost::system::error_code ec;
      (void)boost::asio::ip::make_address(text, ec);
      if (ec) throw std::invalid_argument("--listen takes an IPv4 or IPv6 address such as 0.0.0.0, 127.0.0.1 or ::, got '" + text + "'");
      o.listen = text;
    }
    else if (a == "--port" || a == "--ippdme-port" || a == "--http-port") {
      auto text = value("a port number");
      auto n = protocol::parse_number(text);
      if (!n || *n < 0 || *n > 65535 || *n != static_cast<int>(*n))
        throw std::invalid_argument(std::string(a) + " takes a whole number from 0 to 65535, got '" + text + "'");
      (a == "--port" ? o.port : a == "--ippdme-port" ? o.ippdme_port : o.http_port) = static_cast<int>(*n);
    } else if (a == "--home") o.home = true;
    else if (a == "--no-rt") o.no_realtime = true;
    else if (a == "-dc") o.debug_comm = true;
    else if (a == "-dm") o.debug_motion = true;
    else if (a == "-dt") o.debug_status = true;
    else if (a == "-p") o.timing = true;
    else if (a == "-r") o.reboot = true;
    else if (a == "-v" || a == "--version") o.version = true;
    else if (a == "-h" || a == "--help") o.help = true;
    else throw std::invalid_argument("unknown option '" + std::string(a) + "'");
  }
  return o;
}

}  // namespace imess::app
