// messcap convert to QIF: reads every report whole and checked, then writes the document at once.
#include "qif_convert.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "imess/client/usage_error.hpp"
#include "point_file.hpp"
#include "qif_document.hpp"
#include "text_file.hpp"

namespace imess::messcap {
namespace {

bool is_qif_name(std::string_view name) {
  if (name.size() < 4) return false;
  std::string ext(name.substr(name.size() - 4));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".qif";
}

}  // namespace

bool converts_to_qif(int argc, const char* const argv[]) {
  std::string_view last;
  for (int i = 2; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a.size() > 1 && a.front() == '-') continue;
    last = a;
  }
  return is_qif_name(last);
}

int run_qif_convert(int argc, const char* const argv[]) {
  std::vector<std::string> files;
  bool force = false;
  for (int i = 2; i < argc; ++i) {
    std::string_view a = argv[i];
    if (a == "--force") {
      force = true;
    } else if (a.size() > 1 && a.front() == '-') {
      std::cerr << "messcap: convert to QIF: unknown option '" << a << "'; accepted: --force\n"
                << "usage: messcap convert REPORT.json [REPORT.json ...] OUT.qif [--force]\n";
      return client::kExitUsage;
    } else {
      files.emplace_back(a);
    }
  }
  if (files.size() < 2) {
    std::cerr << "messcap: convert to QIF needs one or more inspection reports (messcap inspect --json) and the QIF "
                 "file; usage: messcap convert REPORT.json [REPORT.json ...] OUT.qif [--force]\n";
    return client::kExitUsage;
  }
  const std::string out = files.back();
  files.pop_back();
  struct stat st {};
  if (!force && ::stat(out.c_str(), &st) == 0) {
    std::cerr << "messcap: '" << out << "' exists; add --force to replace it\n";
    return client::kExitFailure;
  }
  try {
    std::vector<QifRunSource> runs;
    for (const auto& f : files) runs.push_back({parse_saved_inspection(read_text_file(f), f), f});
    write_file_atomically(out, qif_document(runs, utc_time_now()));
    std::cerr << "messcap: " << runs.size() << (runs.size() == 1 ? " inspection run" : " inspection runs")
              << " written to " << out << "\n";
    return client::kExitOk;
  } catch (const std::exception& e) {
    std::cerr << "messcap: convert: " << e.what() << " (nothing written)\n";
    return client::kExitFailure;
  }
}

}  // namespace imess::messcap
