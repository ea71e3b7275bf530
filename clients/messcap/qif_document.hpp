// messcap's QIF 3.0 results document (ANSI/DMSC QIF 3.0, ISO 23952): one or more runs of one
// inspection plan, as their JSON reports hold them, in one complete QIFDocument — the part, the
// plan's features and characteristics as definitions, nominals and items, and one
// MeasurementResults per run with the measured features, their points and the characteristic
// measurements. Millimetres and degrees. Mapping in docs/qif.md.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "saved_inspection.hpp"

namespace imess::messcap {

// Runs that cannot share one document: none, or not of the same plan (part, features,
// characteristics). The message names the run and what differs.
class QifError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct QifRunSource {
  SavedInspection run;
  std::string name;  // the report file, for messages
};

// The whole document. `qpid` is the document's UUID (new_qpid() when empty). `created`: the
// document's TimeCreated (ISO 8601), none when empty.
std::string qif_document(const std::vector<QifRunSource>& runs, const std::string& created = "",
                         const std::string& qpid = "");

// A random (version 4) UUID, as QIF's QPId.
std::string new_qpid();

// Now as ISO 8601 UTC to the second, "2026-11-29T03:40:12Z" (xs:dateTime).
std::string utc_time_now();

}  // namespace imess::messcap
