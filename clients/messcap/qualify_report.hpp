// The report of messcap qualify: a few lines for the terminal and a JSON document
// (docs/clients.md "messcap qualify").
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "qualification.hpp"
#include "qualify_session.hpp"

namespace imess::messcap {

struct QualifyReport {
  ReferenceSphere sphere;
  Touches touches;
  Qualification result;
  QualificationLimits limits;
  std::optional<std::string> refused;  // why it was not qualified, if it was not
};

void print_qualify_report(std::ostream& out, const QualifyReport& r);
std::string qualify_json(const QualifyReport& r);

}  // namespace imess::messcap
