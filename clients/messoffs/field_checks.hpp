// The checks one offset's values get in either table format (JSON, CSV): each throws
// TableError "<where>: expected ..., got ..." where `where` names the file and the key or line.
#pragma once
#include <string>
#include <string_view>

namespace imess::messoffs {

std::string check_name(std::string_view name, const std::string& where);
int check_clamping(double value, const std::string& where);  // a whole number 1..999
int check_p(double value, const std::string& where);         // a whole number kMinP..kMaxP
double check_finite(double value, const std::string& where, std::string_view what);  // "a length in mm"

// "-327.957" -> -327.957 (the whole field, no spaces inside); throws naming `what` otherwise.
double parse_number(std::string_view text, const std::string& where, std::string_view what);

}  // namespace imess::messoffs
