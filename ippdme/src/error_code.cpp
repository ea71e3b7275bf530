// The error table: the spec's number, severity and standard text, once (IPPDME.md §4).
#include "imess/ippdme/error_code.hpp"

#include <array>

namespace imess::ippdme {
namespace {
using E = ErrorCode;
using S = Severity;
constexpr std::array kErrors{
    ErrorInfo{E::BufferFull, S::Info, "Buffer full"},
    ErrorInfo{E::IllegalTag, S::Error, "Illegal tag"},
    ErrorInfo{E::NoSpaceAtPos6, S::Error, "No space at pos. 6"},
    ErrorInfo{E::TransactionAborted, S::Error, "Transaction aborted (Use ClearAllErrors To Continue)"},
    ErrorInfo{E::IllegalCharacter, S::OperatorError, "Illegal character"},
    ErrorInfo{E::ProtocolError, S::OperatorError, "Protocol error"},
    ErrorInfo{E::EmergencyStop, S::OperatorError, "Emergency stop"},
    ErrorInfo{E::UnsupportedCommand, S::OperatorError, "Unsupported command"},
    ErrorInfo{E::IncorrectArguments, S::OperatorError, "Incorrect arguments"},
    ErrorInfo{E::ControllerCommunicationsFailure, S::Fatal, "Controller communications failure"},
    ErrorInfo{E::ArgumentOutOfRange, S::Warning, "Argument out of range"},
    ErrorInfo{E::ArgumentNotRecognized, S::OperatorError, "Argument not recognized"},
    ErrorInfo{E::ArgumentNotSupported, S::OperatorError, "Argument not supported"},
    ErrorInfo{E::IllegalCommand, S::OperatorError, "Illegal command"},
    ErrorInfo{E::BadContext, S::OperatorError, "Bad context"},
    ErrorInfo{E::BadArgument, S::OperatorError, "Bad argument"},
    ErrorInfo{E::BadProperty, S::OperatorError, "Bad property"},
    ErrorInfo{E::ErrorProcessingMethod, S::OperatorError, "Error processing method"},
    ErrorInfo{E::NoDaemonsAreActive, S::Warning, "No daemons are active"},
    ErrorInfo{E::DaemonDoesNotExist, S::Error, "Daemon does not exist"},
    ErrorInfo{E::UseClearAllErrorsToContinue, S::Error, "Use ClearAllErrors to continue"},
    ErrorInfo{E::DaemonAlreadyExists, S::Error, "Daemon already exists"},
    ErrorInfo{E::MachineInErrorState, S::OperatorError, "Machine in error state"},
    ErrorInfo{E::IllegalTouch, S::Error, "Illegal touch"},
    ErrorInfo{E::NoTouch, S::Error, "No touch"},
    ErrorInfo{E::ErrorDuringHome, S::OperatorError, "Error during home"},
    ErrorInfo{E::SurfaceNotFound, S::Error, "Surface not found"},
    ErrorInfo{E::ThetaOutOfRange, S::OperatorError, "Theta out of range"},
    ErrorInfo{E::TargetPositionOutOfMachineVolume, S::OperatorError, "Target position out of machine volume"},
    ErrorInfo{E::AirPressureOutOfRange, S::OperatorError, "Air pressure out of range"},
    ErrorInfo{E::VectorHasNoNorm, S::Error, "Vector has no norm"},
    ErrorInfo{E::ToolNotFound, S::OperatorError, "Tool not found"},
    ErrorInfo{E::ToolNotDefined, S::OperatorError, "Tool not defined"},
    ErrorInfo{E::ToolNotCalibrated, S::OperatorError, "Tool not calibrated"},
    ErrorInfo{E::MachineLimitEncountered, S::OperatorError, "Machine limit encountered [Move Out Of Limits]"},
    ErrorInfo{E::Collision, S::OperatorError, "Collision"},
};
}  // namespace

std::span<const ErrorInfo> error_table() { return kErrors; }

const ErrorInfo& error_info(ErrorCode code) {
  for (const auto& e : kErrors)
    if (e.code == code) return e;
  return kErrors[5];  // ProtocolError; unreachable for a declared code
}

bool is_refusal(ErrorCode code) {
  switch (code) {
    case E::IllegalTag: case E::NoSpaceAtPos6: case E::IllegalCharacter: case E::ProtocolError:
    case E::UnsupportedCommand: case E::IncorrectArguments: case E::ArgumentNotRecognized:
    case E::ArgumentNotSupported: case E::IllegalCommand: case E::BadContext: case E::BadArgument:
    case E::BadProperty: case E::DaemonDoesNotExist: case E::DaemonAlreadyExists:
    case E::ThetaOutOfRange: case E::VectorHasNoNorm:
      return true;
    default:
      return false;
  }
}

bool is_query(std::string_view method) {
  constexpr std::string_view kQueries[] = {"GetErrorInfo", "GetProp",       "GetPropE",        "EnumProp",
                                           "EnumAllProp",  "GetDMEVersion", "IsHomed",         "IsUserEnabled",
                                           "GetMachineClass", "GetErrStatusE", "GetXtdErrStatus", "Get",
                                           "EnumTools",    "FindTool",      "GetChangeToolAction", "GetCoordSystem",
                                           "GetCsyTransformation"};
  for (auto q : kQueries)
    if (q == method) return true;
  return false;
}

bool enters_error_state(ErrorCode code) { return !is_refusal(code) && error_info(code).severity >= Severity::Error; }

bool enters_error_state(ErrorCode code, std::string_view method) { return enters_error_state(code) && !is_query(method); }

const ErrorInfo* find_error(int number) {
  for (const auto& e : kErrors)
    if (number_of(e.code) == number) return &e;
  return nullptr;
}

}  // namespace imess::ippdme
