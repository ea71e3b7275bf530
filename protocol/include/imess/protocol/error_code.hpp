// Stable numeric error codes of the wire protocol (`Err <code> <text>`). Never renumber;
// the table in docs/protocol.md is checked against this list by the tests.
#pragma once
#include <span>
#include <string_view>

namespace imess::protocol {

enum class ErrorCode : int {
  // 1xx: the line itself
  UnknownCommand = 100,   // verb not in the table
  BadArguments = 101,     // wrong number of arguments
  BadNumber = 102,        // an argument is not a finite decimal number
  LineTooLong = 103,      // longer than kMaxLineLength; the rest of it was discarded
  BadCharacter = 104,     // control or non-ASCII byte in a line
  BadValue = 105,         // a number outside the accepted range
  // 2xx: the machine's state forbids it now
  TipTouched = 200,       // probe deflected: move the tip free by hand first
  IntoLimit = 201,        // every requested axis points further into its limit switch
  Busy = 202,             // another operation (homing, retract) owns the machine
  QueueFull = 203,        // command queue to the motion loop is full; retry
  NotSimulated = 204,     // a simulator-only command on real hardware
  LoopsClosed = 205,      // hand push while the servo loops hold the axes
  OutOfTravel = 206,      // target outside the configured travel
  Faulted = 207,          // machine in fault state; clear with Reset
  TooManyClients = 208,   // the connection limit is reached; the connection is closed
  NotInControl = 209,     // another client controls the machine (the text names it); StopMv is open to all
  HostNotAllowed = 210,   // this host may not connect / control / force a take-over (configuration)
  Dropped = 211,          // the daemon closes this connection: it stopped reading, or fell silent
  NotInJournal = 212,     // Replay of hits rotated out of the journal; the text names the oldest kept
  BadProgram = 213,       // a program refused before anything moved: line:column, what was found, what is accepted
  // 3xx: parameters
  UnknownParameter = 300, // Get/Set of a name that does not exist
  ReadOnlyParameter = 301,
  // 5xx: the daemon itself
  Internal = 500,
};

struct ErrorInfo {
  ErrorCode code;
  std::string_view name;     // short identifier, as in the docs table
  std::string_view meaning;  // one line for humans
};

// Every code with its name and meaning, in numeric order.
std::span<const ErrorInfo> error_table();
const ErrorInfo& error_info(ErrorCode code);

}  // namespace imess::protocol
