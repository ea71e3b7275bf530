// messcard's command line.
#include "options.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string_view>

namespace imess::messcard {

const char* usage_text() {
  return "usage: messcard (--pty PATH | --device TTY) --config FILE [--baud N] [--drop RATE] [--corrupt RATE]\n"
         "                [--faults-at-ms T] [--stall-ms N [--stall-at-ms T]] [--seed N] [--no-rt]\n"
         "  The emulated servo card as a program of its own, on a serial line in real time.\n"
         "  --pty PATH      create a pseudo-terminal; PATH becomes a symbolic link to its slave side\n"
         "  --device TTY    serve an existing tty instead (a USB-serial adapter looped to another)\n"
         "  --config FILE   a messd configuration: its \"sim\" section is the machine (mechanics, probe,\n"
         "                  scene), its backend's \"baud\" the line's rate\n"
         "  --baud N        the line's rate (overrides the configuration; default 115200)\n"
         "  --drop RATE     lose each byte with this probability (0-1), both directions\n"
         "  --corrupt RATE  flip one bit of each byte with this probability (0-1), both directions\n"
         "  --faults-at-ms T  --drop and --corrupt begin T ms after the host started the stream\n"
         "                  (default 0: from the first byte, set-up included), or on SIGUSR2\n"
         "  --stall-ms N    stop answering for N ms once (reading nothing, sending nothing; the firmware\n"
         "                  runs on), --stall-at-ms T after the host started the stream (default 1000),\n"
         "                  or at once on SIGUSR1\n"
         "  --seed N        the fault injection's random seed (default 1)\n"
         "  --no-rt         do not ask for SCHED_FIFO (asked for by default, used where permitted: the\n"
         "                  card is hardware, a late tick on a loaded host is a late status frame)\n"
         "  -h, --help      this text\n"
         "  SIGTERM or SIGINT pulls the cable: the line goes, the card runs on until its watchdog has\n"
         "  braked (shown), then messcard ends.\n";
}

namespace {
double number(std::string_view opt, const std::string& text, double min, double max) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v) || v < min || v > max) {
    char range[64];
    std::snprintf(range, sizeof range, "%g to %g", min, max);
    throw std::invalid_argument(std::string(opt) + " takes a number from " + range + ", got '" + text + "'");
  }
  return v;
}
}  // namespace

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    auto value = [&](const char* what) -> std::string {
      if (i + 1 >= argc || argv[i + 1][0] == '\0') throw std::invalid_argument(std::string(a) + " needs " + what);
      return argv[++i];
    };
    if (a == "--pty") o.pty = value("a path for the link to the pseudo-terminal");
    else if (a == "--device") o.device = value("a tty such as /dev/ttyUSB1");
    else if (a == "--config") o.config = value("a configuration file");
    else if (a == "--baud") o.baud = static_cast<int>(number(a, value("a baud rate"), 9600, 4e6));
    else if (a == "--drop") o.drop = number(a, value("a rate"), 0, 1);
    else if (a == "--corrupt") o.corrupt = number(a, value("a rate"), 0, 1);
    else if (a == "--faults-at-ms") o.faults_at_ms = number(a, value("milliseconds"), 0, 3.6e6);
    else if (a == "--stall-ms") o.stall_ms = number(a, value("milliseconds"), 0, 3.6e6);
    else if (a == "--stall-at-ms") o.stall_at_ms = number(a, value("milliseconds"), 0, 3.6e6);
    else if (a == "--seed") o.seed = static_cast<unsigned>(number(a, value("a whole number"), 0, 4e9));
    else if (a == "--no-rt") o.realtime = false;
    else if (a == "-h" || a == "--help") o.help = true;
    else throw std::invalid_argument("unknown option '" + std::string(a) + "'");
  }
  if (o.help) return o;
  if (o.pty.empty() == o.device.empty()) throw std::invalid_argument("give exactly one of --pty PATH and --device TTY");
  if (o.config.empty()) throw std::invalid_argument("--config FILE is needed (a configuration with a \"sim\" section)");
  return o;
}

}  // namespace imess::messcard
