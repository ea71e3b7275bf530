// The words the daemon uses on the wire for the motion loop's enums: modes, warnings,
// faults, refusals (with their protocol error codes), command verbs.
#pragma once
#include <string>
#include <string_view>

#include "imess/core/core_types.hpp"
#include "imess/protocol/error_code.hpp"

namespace imess::net {

std::string_view mode_name(core::Mode m);
std::string_view command_verb(core::CommandKind k);

struct Wording {
  std::string_view name;  // one CamelCase word
  std::string_view text;  // for people
};
Wording warning_wording(core::Warning w);
Wording fault_wording(core::FaultKind f);
// The reason word of `Failed id <Reason> <text>` (the one list of them: core::FailReason).
Wording fail_wording(core::FailReason f);
// The event `Failed id <Reason> <text>`.
std::string failed_line(std::uint32_t id, core::FailReason why);

struct RefusalWording {
  protocol::ErrorCode code;
  std::string_view text;
};
RefusalWording refusal_wording(core::Refusal r);

}  // namespace imess::net
