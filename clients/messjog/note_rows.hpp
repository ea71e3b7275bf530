// The jog panel's messages as screen rows: each message wrapped at word boundaries to the
// terminal's width (a continuation indented), the newest at the bottom, as many as fit.
#pragma once
#include <deque>
#include <string>
#include <vector>

namespace imess::messjog {

// `message` in rows of at most `width` characters: broken at blanks, a word longer than a row
// broken inside it; rows after the first start with two blanks. Never an empty list.
std::vector<std::string> wrap_message(const std::string& message, int width);
// The last `rows` rows of every note wrapped, oldest note first (a note cut at the top keeps
// its end, the part nearest the newer notes).
std::vector<std::string> note_rows(const std::deque<std::string>& notes, int width, int rows);

}  // namespace imess::messjog
