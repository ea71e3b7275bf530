// Reading back the JSON object `messcap fit` prints into an exchange::FitReport, checking that
// it carries what its kind needs; `messcap relate` reads its two features this way.
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>

#include "imess/exchange/fit_report.hpp"

namespace imess::messcap {

// A fit object that cannot be used; the message names the source, the key and what is accepted.
struct FitJsonError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One JSON object as `messcap fit` prints it (`type` plus the fields of its kind; unknown keys
// are ignored). Directions are made unit length. `source` names the input in messages
// ("a.json", "<stdin> line 2").
exchange::FitReport parse_fit_json(std::string_view text, const std::string& source);

}  // namespace imess::messcap
