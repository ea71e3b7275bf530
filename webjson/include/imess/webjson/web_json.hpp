// The web panel's JSON protocol: the MESSD line protocol one to one, as WebSocket text
// messages (docs/web.md, "The JSON protocol").
//   browser -> messd: {"cmd":"StartMv","args":[0,0,-20]} is the line "StartMv 0 0 -20";
//                     {"cmd":""} the blank keep-alive line; {"line":"GoTo 1 2 3"} a line as typed;
//                     {"cmd":"Upload","args":["p.ngc"],"lines":[...]} the upload with its "." line.
//   messd -> browser: every line as {"type":<verb>, <its fields by name>, "line":<the line>}.
#pragma once
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

namespace imess::webjson {

// A message that is no command: the line protocol's error code (101: the message's shape,
// 103: too long, 104: a character no line may hold) and a text saying what was wrong and
// what is accepted.
struct Refusal {
  int code = 101;
  std::string text;
};

// The longest message accepted (an Upload's lines travel in one).
inline constexpr std::size_t kMaxMessageBytes = 1 << 20;

// One WebSocket text message to the lines (without "\n") it stands for, or why not.
std::variant<std::vector<std::string>, Refusal> command_lines(std::string_view message);

// One line messd sends (without "\n") as its JSON event; never throws (bytes that are not
// UTF-8 are replaced when dumped).
nlohmann::ordered_json event_json(std::string_view line);
// The same as text, one WebSocket message.
std::string event_text(std::string_view line);
// And back: the line an event stands for, made from its fields alone ("line" is not read);
// empty when `event` is not one event_json makes.
std::string event_line(const nlohmann::json& event);

// The event types with fields of their own, in the order of docs/web.md's table.
std::vector<std::string_view> event_types();

}  // namespace imess::webjson
