// bench_echo: the reference server of bench_net (the loopback floor). Prints
// "bench_echo: OK, listening on 127.0.0.1:PORT" and serves until SIGTERM or SIGINT.
#include <sys/resource.h>

#include <utility>  // before Asio: its awaitable.hpp uses std::exchange without it
#include <boost/asio.hpp>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

#include "echo_server.hpp"

namespace {
int usage(const std::string& why) {
  std::fprintf(stderr,
               "bench_echo: %s\nusage: bench_echo --mode echo|broadcast|timer [--hz R] [--port P]\n"
               "  echo: each line back to its sender; broadcast: each line to every client;\n"
               "  timer: a CurrCor-sized line stamped with CLOCK_MONOTONIC to every client R times a second\n"
               "  (--hz 0.1 to 10000, required with timer); --port 0 to 65535 (default 0: a free port)\n",
               why.c_str());
  return 2;
}

bool parse(const std::string& text, double lo, double hi, double& out) {
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && p == text.data() + text.size() && std::isfinite(out) && out >= lo && out <= hi;
}
}  // namespace

int main(int argc, char** argv) {
  std::string mode;
  double hz = 0, port = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") return usage("the loopback floor of bench_net"), 0;
    if (i + 1 >= argc) return usage(a + " needs a value (or is not an option)");
    const std::string v = argv[++i];
    if (a == "--mode") mode = v;
    else if (a == "--hz") {
      if (!parse(v, 0.1, 10000, hz)) return usage("--hz takes a number from 0.1 to 10000, got '" + v + "'");
    } else if (a == "--port") {
      if (!parse(v, 0, 65535, port) || port != std::floor(port)) return usage("--port takes a whole number from 0 to 65535, got '" + v + "'");
    } else
      return usage("unknown option '" + a + "'");
  }
  imess::bench::EchoMode m;
  if (mode == "echo") m = imess::bench::EchoMode::Echo;
  else if (mode == "broadcast") m = imess::bench::EchoMode::Broadcast;
  else if (mode == "timer") m = imess::bench::EchoMode::Timer;
  else return usage("--mode takes echo, broadcast or timer, got '" + mode + "'");
  if (m == imess::bench::EchoMode::Timer && hz <= 0) return usage("--mode timer needs --hz");

  rlimit lim{};  // as many connections as the hard limit allows
  if (getrlimit(RLIMIT_NOFILE, &lim) == 0 && lim.rlim_cur < lim.rlim_max) {
    lim.rlim_cur = lim.rlim_max;
    setrlimit(RLIMIT_NOFILE, &lim);
  }
  try {
    boost::asio::io_context io(1);
    imess::bench::EchoServer server(io, m, hz, static_cast<std::uint16_t>(port));
    boost::asio::signal_set stop(io, SIGTERM, SIGINT);
    stop.async_wait([&](boost::system::error_code, int) { io.stop(); });
    std::printf("bench_echo: OK, listening on 127.0.0.1:%u\n", server.port());
    std::fflush(stdout);
    io.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_echo: %s\n", e.what());
    return 1;
  }
  return 0;
}
