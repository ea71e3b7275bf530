// messprog's command line: the command (check, plot, run), the program FILE and the options
// each command takes, and the --help text.
#pragma once
#include <optional>
#include <string>

#include "imess/client/endpoint.hpp"
#include "imess/programs/check.hpp"

namespace imess::messprog {

enum class Command { Check, Plot, Run };

struct ProgOptions {
  Command command = Command::Check;
  std::string file;                                 // the program
  programs::Language lang = programs::Language::Gcode;  // from --lang, else the extension
  std::optional<std::string> axes;                  // --axes LETTERS (check, plot)
  std::optional<double> travel_min, travel_max;     // --travel MIN:MAX (check, plot)
  std::optional<std::string> from;                  // --from X,Y,Z: the start pose (check, plot)
  std::optional<std::string> config;                // --config FILE: messd's machine (check, plot)
  bool canon = false;                               // check --canon: LinuxCNC's canonical calls
  std::string output;                               // plot: -o OUT.svg
  client::Endpoint endpoint;                        // run: HOST[:PORT]
  bool detached = false;                            // run: Run detached
  bool help = false;
};

// Throws client::UsageError naming the bad argument and what is accepted.
ProgOptions parse_prog_options(int argc, const char* const argv[]);

std::string prog_usage();

}  // namespace imess::messprog
