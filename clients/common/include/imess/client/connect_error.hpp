// ConnectError: messd could not be reached. what() is the full sentence a client prints after
// its name, e.g. "no partner on localhost:1066 (connection refused) — is messd running?".
#pragma once
#include <stdexcept>
#include <string>

#include "imess/client/endpoint.hpp"

namespace imess::client {

class ConnectError : public std::runtime_error {
 public:
  enum class Kind { Unreachable, NotResolved };

  ConnectError(const Endpoint& where, Kind kind, const std::string& reason);

  Kind kind() const { return kind_; }
  const std::string& reason() const { return reason_; }  // "connection refused", "timed out after 2000 ms"

 private:
  Kind kind_;
  std::string reason_;
};

}  // namespace imess::client
