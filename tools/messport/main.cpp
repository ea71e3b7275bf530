// messport: read, write and watch I/O ports — the simulated port space a messd simulator
// shares through its port file, or real ports (x86 ioperm, ppdev). Every value is shown
// unsigned, signed and in hex, as the MRM manual's port tool did.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "imess/hal/port_io.hpp"

namespace {

const char* kUsage =
    "usage: messport [--file PATH | --x86 | --ppdev DEVICE] [--8] COMMAND\n"
    "  read  PORT [COUNT]            show COUNT ports from PORT (default 1)\n"
    "  write PORT VALUE              set a port (VALUE decimal, -signed, or 0x hex)\n"
    "  watch PORT [COUNT]            show the ports whenever they change (Ctrl-C ends)\n"
    "        [--interval MS] [--times N]\n"
    "  --file PATH   the simulator's port file (default $IMESS_PORT_FILE, else /tmp/imess-ports-shd)\n"
    "  --x86         real ports via ioperm (root or CAP_SYS_RAWIO)\n"
    "  --ppdev DEV   a real parallel port via /dev/parportN (ports base..base+2, base = PORT)\n"
    "  --8           8-bit accesses (default 16-bit; the parallel port registers are 8-bit)\n"
    "PORT: 0x300, 768, ...\n";

long number(const std::string& s, const char* what) {
  try {
    std::size_t used = 0;
    long v = std::stol(s, &used, 0);
    if (used == s.size()) return v;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument(std::string(what) + " '" + s + "' is not a number (decimal or 0x hex)");
}

std::string show(std::uint16_t port, unsigned value, bool eight) {
  char b[128];
  long s = eight ? static_cast<long>(static_cast<std::int8_t>(value)) : static_cast<long>(static_cast<std::int16_t>(value));
  std::snprintf(b, sizeof b, "0x%04X  u %5u  s %6ld  hex 0x%0*X", port, value, s, eight ? 2 : 4, value);
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string file = std::getenv("IMESS_PORT_FILE") ? std::getenv("IMESS_PORT_FILE") : "/tmp/imess-ports-shd";
  std::string mode = "sim", device;
  bool eight = false;
  long interval_ms = 100, times = -1;
  std::vector<std::string> words;
  try {
    for (std::size_t i = 0; i < args.size(); ++i) {
      const auto& a = args[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
        return args[++i];
      };
      if (a == "--help" || a == "-h") {
        std::fputs(kUsage, stdout);
        return 0;
      } else if (a == "--file") {
        file = value();
      } else if (a == "--x86") {
        mode = "x86";
      } else if (a == "--ppdev") {
        mode = "ppdev";
        device = value();
      } else if (a == "--8") {
        eight = true;
      } else if (a == "--interval") {
        interval_ms = number(value(), "interval");
      } else if (a == "--times") {
        times = number(value(), "times");
      } else {
        words.push_back(a);
      }
    }
    if (words.size() < 2) throw std::invalid_argument("a command and a port are needed");
    const std::string cmd = words[0];
    long port = number(words[1], "port");
    if (port < 0 || port > 0xFFFF) throw std::invalid_argument("port must be from 0 to 0xFFFF");
    long count = 1;
    if ((cmd == "read" || cmd == "watch") && words.size() > 2) count = number(words[2], "count");
    if (count < 1 || port + count > 0x10000) throw std::invalid_argument("count out of range");

    std::unique_ptr<imess::hal::PortIo> io;
    if (mode == "sim")
      io = std::make_unique<imess::hal::SharedPortSpace>(file);
    else if (mode == "x86")
      io = std::make_unique<imess::hal::X86PortIo>(static_cast<std::uint16_t>(port), static_cast<int>(count) * (eight ? 1 : 2));
    else
      io = std::make_unique<imess::hal::PpdevPortIo>(device, static_cast<std::uint16_t>(port));
    auto read = [&](std::uint16_t p) -> unsigned { return eight ? io->in8(p) : io->in16(p); };

    if (cmd == "read") {
      for (long i = 0; i < count; ++i) std::printf("%s\n", show(static_cast<std::uint16_t>(port + i), read(static_cast<std::uint16_t>(port + i)), eight).c_str());
    } else if (cmd == "write") {
      if (words.size() != 3) throw std::invalid_argument("write needs PORT VALUE");
      long v = number(words[2], "value");
      long lo = eight ? -128 : -32768, hi = eight ? 255 : 65535;
      if (v < lo || v > hi) throw std::invalid_argument("value out of range for a " + std::string(eight ? "8" : "16") + "-bit port");
      if (eight)
        io->out8(static_cast<std::uint16_t>(port), static_cast<std::uint8_t>(v));
      else
        io->out16(static_cast<std::uint16_t>(port), static_cast<std::uint16_t>(v));
      std::printf("%s\n", show(static_cast<std::uint16_t>(port), read(static_cast<std::uint16_t>(port)), eight).c_str());
    } else if (cmd == "watch") {
      std::vector<long> last(static_cast<std::size_t>(count), -1);
      for (long n = 0; times < 0 || n < times; ++n) {
        for (long i = 0; i < count; ++i) {
          unsigned v = read(static_cast<std::uint16_t>(port + i));
          if (static_cast<long>(v) != last[static_cast<std::size_t>(i)]) {
            std::printf("%s\n", show(static_cast<std::uint16_t>(port + i), v, eight).c_str());
            last[static_cast<std::size_t>(i)] = v;
          }
        }
        std::fflush(stdout);
        std::this_thread::sleep_for(std::chrono::milliseconds(interval_ms));
      }
    } else {
      throw std::invalid_argument("unknown command '" + cmd + "'");
    }
    if (io->errors() != 0) {
      std::fprintf(stderr, "messport: %lu accesses hit no register (%s)\n", io->errors(), io->describe().c_str());
      return 1;
    }
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "messport: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "messport: %s\n", e.what());
    return 1;
  }
  return 0;
}
