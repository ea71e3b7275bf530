// The wording of "cannot reach messd", kept close to the 1996 "no Partner on Port 1066".
#include "imess/client/connect_error.hpp"

namespace imess::client {
namespace {

std::string sentence(const Endpoint& where, ConnectError::Kind kind, const std::string& reason) {
  if (kind == ConnectError::Kind::NotResolved)
    return "cannot resolve host '" + where.host + "' (" + reason + ") — check the HOST[:PORT] argument";
  return "no partner on " + where.to_string() + " (" + reason + ") — is messd running?";
}

}  // namespace

ConnectError::ConnectError(const Endpoint& where, Kind kind, const std::string& reason)
    : std::runtime_error(sentence(where, kind, reason)), kind_(kind), reason_(reason) {}

}  // namespace imess::client
