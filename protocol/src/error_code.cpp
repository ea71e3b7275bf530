// The error-code table: names and meanings for docs, Help and tests.
#include "imess/protocol/error_code.hpp"

#include <array>

namespace imess::protocol {
namespace {
constexpr std::array kErrors{
    ErrorInfo{ErrorCode::UnknownCommand, "UnknownCommand", "the verb is not known; Help lists the commands"},
    ErrorInfo{ErrorCode::BadArguments, "BadArguments", "wrong number of arguments for the verb"},
    ErrorInfo{ErrorCode::BadNumber, "BadNumber", "an argument is not a finite decimal number"},
    ErrorInfo{ErrorCode::LineTooLong, "LineTooLong", "the line exceeds the maximum length and was discarded"},
    ErrorInfo{ErrorCode::BadCharacter, "BadCharacter", "the line holds a control or non-ASCII byte"},
    ErrorInfo{ErrorCode::BadValue, "BadValue", "a value is outside its accepted range"},
    ErrorInfo{ErrorCode::TipTouched, "TipTouched", "the probe tip is deflected: free it by hand before moving"},
    ErrorInfo{ErrorCode::IntoLimit, "IntoLimit", "the move points further into an active limit switch"},
    ErrorInfo{ErrorCode::Busy, "Busy", "another operation owns the machine (homing, retract)"},
    ErrorInfo{ErrorCode::QueueFull, "QueueFull", "the motion loop's command queue is full; retry"},
    ErrorInfo{ErrorCode::NotSimulated, "NotSimulated", "simulator-only command on real hardware"},
    ErrorInfo{ErrorCode::LoopsClosed, "LoopsClosed", "the position loops are closed; hand pushes need them open"},
    ErrorInfo{ErrorCode::OutOfTravel, "OutOfTravel", "the target lies outside the configured travel"},
    ErrorInfo{ErrorCode::Faulted, "Faulted", "the machine is in fault state; Reset clears it"},
    ErrorInfo{ErrorCode::TooManyClients, "TooManyClients", "the connection limit is reached; this connection is closed"},
    ErrorInfo{ErrorCode::NotInControl, "NotInControl", "another client controls the machine; StopMv is open to all"},
    ErrorInfo{ErrorCode::HostNotAllowed, "HostNotAllowed", "this host may not connect, control or force a take-over"},
    ErrorInfo{ErrorCode::Dropped, "Dropped", "the connection is closed: the client stopped reading or fell silent"},
    ErrorInfo{ErrorCode::NotInJournal, "NotInJournal", "those hits were rotated out of the journal; the text names the oldest seq kept"},
    ErrorInfo{ErrorCode::BadProgram, "BadProgram", "the program was refused before anything moved; the text names line:column, what was found and what is accepted"},
    ErrorInfo{ErrorCode::UnknownParameter, "UnknownParameter", "no parameter of that name; Get lists them"},
    ErrorInfo{ErrorCode::ReadOnlyParameter, "ReadOnlyParameter", "the parameter can be read but not set"},
    ErrorInfo{ErrorCode::Internal, "Internal", "the daemon failed internally; see its log"},
};
}  // namespace

std::span<const ErrorInfo> error_table() { return kErrors; }

const ErrorInfo& error_info(ErrorCode code) {
  for (const auto& e : kErrors)
    if (e.code == code) return e;
  return kErrors.back();
}

}  // namespace imess::protocol
