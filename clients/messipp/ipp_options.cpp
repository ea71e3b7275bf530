// messipp's command line and --help text. --timeout takes its value as the next argument or
// after '=' ("--timeout 60", "--timeout=60"), as messprog's options do.
#include "ipp_options.hpp"

#include <charconv>
#include <cmath>
#include <string_view>

#include "imess/client/usage_error.hpp"

namespace imess::messipp {
namespace {

using client::UsageError;

std::chrono::milliseconds timeout_value(std::string_view text) {
  double seconds = -1;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seconds);
  // A day is far beyond any move; the bound keeps the milliseconds in range.
  if (text.empty() || ec != std::errc{} || end != text.data() + text.size() || !(seconds >= 0) || seconds > 86400)
    throw UsageError("--timeout '" + std::string(text) +
                     "': accepted a number of seconds 0..86400 (0: wait as long as it takes), e.g. --timeout 120");
  return std::chrono::milliseconds(static_cast<long long>(std::llround(seconds * 1000)));
}

}  // namespace

IppOptions parse_ipp_options(int argc, const char* const argv[]) {
  IppOptions o;
  bool have_host = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--raw") {
      o.raw = true;
    } else if (a == "--timeout") {
      if (i + 1 >= argc) throw UsageError("--timeout needs a value: a number of seconds, e.g. --timeout 120");
      o.timeout = timeout_value(argv[++i]);
    } else if (a.rfind("--timeout=", 0) == 0) {
      o.timeout = timeout_value(a.substr(10));
    } else if (a.size() > 1 && a.front() == '-') {
      throw UsageError("unknown option '" + std::string(a) + "'; accepted: --raw, --timeout S, --help");
    } else {
      client::take_host_argument(a, o.endpoint, have_host);
    }
  }
  return o;
}

std::string ipp_usage() {
  return "usage: messipp [HOST[:PORT]] [--raw] [--timeout S]\n"
         "Talks I++ DME to messd by hand: type a method call, e.g. StartSession() or\n"
         "GoTo(X(10), Y(20)), and messipp sends it with the next tag — 00001, 00002, ...\n"
         "for the normal queue, E0001, E0002, ... for the fast queue (AbortE, GetErrStatusE,\n"
         "GetPropE, SetPropE, OnMoveReportE). A line typed with its tag (00042 Get(X())) goes\n"
         "as typed. Every line the server sends is printed as it arrives. HOST defaults to\n"
         "127.0.0.1, PORT to 1294 (messd's I++ DME port).\n"
         "\n"
         "Lines are read from stdin, a terminal or a pipe; blank lines are skipped. A line\n"
         "goes out after the previous one's Ack (&). A line the I++ DME parser refuses is\n"
         "not sent: messipp prints the error the server would answer, and the session does\n"
         "not fall into its error state. 'quit' or the end of input (Ctrl-D) ends, once every\n"
         "line sent got its '%'.\n"
         "When stdin is not a terminal, each line sent is printed too, as '> 00001 ...', and a\n"
         "line with a command tag waits until everything before it is complete: the output\n"
         "reads as a transcript.\n"
         "\n"
         "  --raw        send lines unchecked (only tagged), to try the server's own errors\n"
         "  --timeout S  give up when an answer messipp waits for (the Ack before the next line,\n"
         "               the '%'s before it ends) takes longer than S seconds; default 30,\n"
         "               0 waits as long as it takes (a piped GoTo longer than 30 s needs it)\n"
         "  -h, --help   this text\n"
         "\n"
         "Exit status: 0 when the input ended and every line sent was answered; 1 when messd\n"
         "cannot be reached, closes the connection first, an answer took longer than the\n"
         "timeout, Ctrl-C came with answers missing, or (stdin not a terminal) a line was\n"
         "refused and not sent; 2 on bad arguments.\n";
}

}  // namespace imess::messipp
