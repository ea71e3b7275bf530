// How messmon prints one received line: "<time> <line>", or a JSON object per line with the
// message type and its parsed fields ({"t":..,"line":..,"type":"MeasPt","x":..,"y":..,"z":..}).
#pragma once
#include <string>
#include <string_view>

namespace imess::messmon {

std::string text_line(std::string_view time, std::string_view line);
std::string json_line(std::string_view time, std::string_view line);

// The "type" field: CurrCor, MeasPt, State, Limit, Warn, Fault, Homed, Ok, Err, Data, Other.
std::string message_type(std::string_view line);

}  // namespace imess::messmon
