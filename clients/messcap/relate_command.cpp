// messcap relate: two fit objects in (two files, or two lines on stdin), one relation out.
#include "relate_command.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

#include "feature_relation.hpp"
#include "fit_json_input.hpp"
#include "imess/client/usage_error.hpp"

namespace imess::messcap {
namespace {

struct Source {
  std::string name;  // for messages
  std::string text;  // one JSON object
};

std::string read_all(std::istream& in) {
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FitJsonError("cannot read '" + path + "': " + std::strerror(errno));
  return read_all(in);
}

// stdin: the two objects on their own lines, as two `messcap fit` runs print them.
std::vector<Source> stdin_sources() {
  std::istringstream in(read_all(std::cin));
  std::vector<Source> out;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    out.push_back({"<stdin> line " + std::to_string(number), line});
  }
  if (out.size() != 2)
    throw FitJsonError("<stdin>: expected two fit objects, one per line (as messcap fit prints them), found " +
                       std::to_string(out.size()));
  return out;
}

}  // namespace

std::string relate_usage() {
  return "usage: messcap relate A B\n"
         "       messcap relate [-]\n"
         "Distance and angle between two fitted features. A and B are files each holding the\n"
         "JSON object messcap fit prints; with '-' or nothing, stdin holds the two objects, one\n"
         "per line. A is the reference. Prints one JSON object: distance, distance_rule, from\n"
         "(on A), to (on B), angle_deg (0..90), angle_rule, and notes saying why a value is\n"
         "missing (non-parallel planes have no distance, a sphere no angle).\n"
         "Exit status: 0 related; 1 an input cannot be read or is not a usable fit; 2 bad arguments.\n";
}

int run_relate_command(int argc, const char* const argv[]) {
  std::vector<std::string> inputs;
  try {
    for (int i = 2; i < argc; ++i) {
      std::string a = argv[i];
      if (a == "-h" || a == "--help") {
        std::cout << relate_usage();
        return client::kExitOk;
      }
      if (a.size() > 1 && a.front() == '-')
        throw client::UsageError("relate: unknown option '" + a + "'; usage: messcap relate A B | -");
      inputs.push_back(a);
    }
    const bool from_stdin = inputs.empty() || (inputs.size() == 1 && inputs[0] == "-");
    if (!from_stdin && inputs.size() != 2)
      throw client::UsageError("relate needs two fit files A B (or '-' for both on stdin), got " +
                               std::to_string(inputs.size()) + " argument(s)");
    if (inputs.size() == 2 && inputs[0] == "-" && inputs[1] == "-")
      throw client::UsageError("relate: stdin can be only one of A and B; use 'messcap relate -' for both");
  } catch (const client::UsageError& e) {
    std::cerr << "messcap: " << e.what() << "\n(try messcap relate --help)\n";
    return client::kExitUsage;
  }

  try {
    std::vector<Source> sources;
    if (inputs.size() == 2) {
      for (const auto& path : inputs)
        sources.push_back(path == "-" ? Source{"<stdin>", read_all(std::cin)} : Source{path, read_file(path)});
    } else {
      sources = stdin_sources();
    }
    const auto a = parse_fit_json(sources[0].text, sources[0].name);
    const auto b = parse_fit_json(sources[1].text, sources[1].name);
    std::cout << to_json(relate(a, b)) << "\n";
  } catch (const FitJsonError& e) {
    std::cerr << "messcap: relate: " << e.what() << "\n";
    return client::kExitFailure;
  }
  return client::kExitOk;
}

}  // namespace imess::messcap
