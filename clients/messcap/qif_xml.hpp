// The XML text of messcap's QIF documents: elements written as escaped text with indentation,
// numbers in their shortest exact form. No XML library: the documents have one fixed shape, are
// written front to back and never read back by messcap (docs/qif.md, "Why no XML library").
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace imess::messcap {

// & < > " ' as entities; characters XML 1.0 cannot carry (control characters other than tab,
// newline, carriage return) as U+FFFD.
std::string xml_escaped(std::string_view text);

// A number as QIF's decimal / double types take it: at most `decimals` decimals, trailing zeros
// dropped, no exponent, never "-0".
std::string qif_number(double v, int decimals = 6);
// "x y z" (QIF's PointType / UnitVectorType lists).
std::string qif_vector(const Eigen::Vector3d& v, int decimals = 6);

class XmlWriter {
 public:
  using Attributes = std::vector<std::pair<std::string, std::string>>;
  explicit XmlWriter(std::string& out) : out_(out) {}
  void open(std::string_view tag, const Attributes& attributes = {});
  void close(std::string_view tag);
  void leaf(std::string_view tag, std::string_view text, const Attributes& attributes = {});
  void empty(std::string_view tag, const Attributes& attributes = {});
  // <tag n="k"><Id>a</Id>…</tag>: QIF's arrays of id references.
  void ids(std::string_view tag, const std::vector<unsigned>& ids);

 private:
  void start(std::string_view tag, const Attributes& attributes);
  std::string& out_;
  int depth_ = 0;
};

}  // namespace imess::messcap
