// The I++ DME error numbers (IPPDME.md §4) with their severity and standard text. The numbers
// are the spec's and never change; docs/ippdme.md lists them, checked by tests/ippdme.
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

namespace imess::ippdme {

// F2 of `Error(F1, F2, F3, "Text")`, by the spec's number.
enum class ErrorCode : std::uint16_t {
  // 0000-0499: protocol and syntax
  BufferFull = 0,
  IllegalTag = 1,
  NoSpaceAtPos6 = 2,
  TransactionAborted = 6,
  IllegalCharacter = 7,
  ProtocolError = 8,
  // 0500-0999: DME and execution
  EmergencyStop = 500,
  UnsupportedCommand = 501,
  IncorrectArguments = 502,
  ControllerCommunicationsFailure = 503,
  ArgumentOutOfRange = 504,
  ArgumentNotRecognized = 505,
  ArgumentNotSupported = 506,
  IllegalCommand = 507,
  BadContext = 508,
  BadArgument = 509,
  BadProperty = 510,
  ErrorProcessingMethod = 511,
  NoDaemonsAreActive = 512,
  DaemonDoesNotExist = 513,
  UseClearAllErrorsToContinue = 514,
  DaemonAlreadyExists = 515,
  // 1000-1499: CartCMM
  MachineInErrorState = 1000,
  IllegalTouch = 1001,
  NoTouch = 1003,
  ErrorDuringHome = 1005,
  SurfaceNotFound = 1006,
  ThetaOutOfRange = 1007,
  TargetPositionOutOfMachineVolume = 1008,
  AirPressureOutOfRange = 1009,
  VectorHasNoNorm = 1010,
  // 1500-1999: tool changer
  ToolNotFound = 1502,
  ToolNotDefined = 1503,
  // 2000-2499: tool
  ToolNotCalibrated = 2000,
  // 2500-2999: axes
  MachineLimitEncountered = 2500,
  Collision = 2504,
};

// F1: how bad it is. Info and Warning do not disturb other commands; Error and above put the
// server into the error state (only GetErrStatusE, GetXtdErrStatus, ClearAllErrors then).
enum class Severity : std::uint8_t { Info = 0, Warning = 1, Error = 2, OperatorError = 3, Fatal = 9 };

struct ErrorInfo {
  ErrorCode code;
  Severity severity;
  std::string_view text;  // the spec's standard text, sent as F4 and by GetErrorInfo
};

// Every error number the library knows, in numeric order.
std::span<const ErrorInfo> error_table();
const ErrorInfo& error_info(ErrorCode code);
// The entry for a number from the wire (GetErrorInfo(n)); null when the spec has none.
const ErrorInfo* find_error(int number);

// Whether the error puts a session into the error state (docs/ippdme.md, "The error state"):
// severity Error and above, except a refusal — an error that only says the line was not
// executed for what it says (its tag, characters, syntax, an argument, an optional command this
// server lacks, a daemon that is not there or already is): nothing was done, nothing changed,
// so the program goes on, as the NIST reference server lets it. What the machine failed to do
// (a move, a touch, homing, a tool change, an abort) stops the program until ClearAllErrors.
bool enters_error_state(ErrorCode code);
// The same for an error answered to `method`: a query (Get…, Enum…, FindTool, IsHomed …)
// changes nothing, so none of its errors enters the error state.
bool enters_error_state(ErrorCode code, std::string_view method);
// Refusals: the numbers for which enters_error_state is false although their severity is 2+.
bool is_refusal(ErrorCode code);
// Methods that only read (their failure changes nothing).
bool is_query(std::string_view method);

constexpr int number_of(ErrorCode code) { return static_cast<int>(code); }
constexpr int severity_number(Severity s) { return static_cast<int>(s); }

}  // namespace imess::ippdme
