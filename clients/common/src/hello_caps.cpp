// The words after "Caps" in messd's Hello answer.
#include "imess/client/hello_caps.hpp"

#include <algorithm>

namespace imess::client {

bool hello_lists_caps(const std::vector<std::string>& hello_args) {
  return std::find(hello_args.begin(), hello_args.end(), "Caps") != hello_args.end();
}

bool hello_has_cap(const std::vector<std::string>& hello_args, std::string_view cap) {
  const auto caps = std::find(hello_args.begin(), hello_args.end(), "Caps");
  return caps != hello_args.end() && std::find(caps + 1, hello_args.end(), cap) != hello_args.end();
}

}  // namespace imess::client
