// Test helper: loads the NIST ATS least-squares reference pairs copied into tests/data/nist-ls.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "imess/metrology/point_file.hpp"

namespace imess::metrology::test {

inline std::filesystem::path nist_dir() { return std::filesystem::path(IMESS_TEST_DATA) / "nist-ls"; }

struct NistCase {
  std::string name;
  std::vector<Eigen::Vector3d> points;
  std::vector<double> fit;  // the .fit values in file order
};

inline std::vector<double> read_fit_values(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::vector<double> v;
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    v.push_back(std::stod(line));
  }
  return v;
}

// Every NAME.ds/NAME.fit pair of one geometry folder, sorted by name; expects `values` per .fit.
inline std::vector<NistCase> load_nist(const std::string& folder, std::size_t values) {
  std::vector<NistCase> cases;
  for (const auto& entry : std::filesystem::directory_iterator(nist_dir() / folder)) {
    if (entry.path().extension() != ".ds") continue;
    NistCase c;
    c.name = entry.path().stem().string();
    c.points = read_points(entry.path());
    auto fit_path = entry.path();
    fit_path.replace_extension(".fit");
    c.fit = read_fit_values(fit_path);
    if (c.fit.size() != values)
      throw std::runtime_error(fit_path.string() + ": expected " + std::to_string(values) + " values");
    cases.push_back(std::move(c));
  }
  std::sort(cases.begin(), cases.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return cases;
}

inline Eigen::Vector3d vec3(const std::vector<double>& v, std::size_t at) {
  return {v.at(at), v.at(at + 1), v.at(at + 2)};
}

}  // namespace imess::metrology::test
