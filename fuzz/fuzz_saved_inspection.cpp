// Fuzz target: a saved messcap inspect JSON report -> read back -> written as a QIF document
// (the report once, and twice as two runs). Only the documented errors may leave: a bad report is
// a SavedInspectionError, never a crash, a hang or another exception; whatever is read is written.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "qif_document.hpp"
#include "saved_inspection.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imess::messcap;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const SavedInspection run = parse_saved_inspection(text, "fuzz.json");
    (void)qif_document({{run, "a.json"}, {run, "b.json"}}, "2026-01-01T00:00:00Z", "00000000-0000-4000-8000-000000000000");
  } catch (const SavedInspectionError&) {
  }
  return 0;
}
