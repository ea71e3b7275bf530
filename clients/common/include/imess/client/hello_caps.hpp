// The capabilities messd names in its answer to Hello, "Ok Hello IMESS 1 messd <version> Caps
// jog goto ... journal ...": what a client checks before it relies on a feature.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace imess::client {

// Whether the arguments of `Ok Hello` (protocol::OkMsg::args) hold a Caps list at all (a
// server from before Caps, or another MESSD server, has none: nothing can be told from it).
bool hello_lists_caps(const std::vector<std::string>& hello_args);
// Whether `cap` is among the Caps.
bool hello_has_cap(const std::vector<std::string>& hello_args, std::string_view cap);

}  // namespace imess::client
