// messcap inspect's reports: the digits that make a verdict visible, and the label placement of
// the HTML report's views (tests/clients/report/check_inspect_html.py checks the page itself in
// Chromium).
#include <catch2/catch.hpp>

#include <cstdio>

#include "inspect_report.hpp"
#include "label_layout.hpp"
#include "number_text.hpp"

using namespace imess::messcap;
using imess::metrology::CharacteristicKind;
using imess::metrology::CharacteristicResult;

namespace {
CharacteristicResult zone(double actual, double width) {
  CharacteristicResult c;
  c.spec.name = "top flatness";
  c.spec.kind = CharacteristicKind::Flatness;
  c.spec.lower = 0;
  c.spec.upper = width;
  c.actual = c.deviation = actual;
  c.in_tolerance = c.deviation >= c.spec.lower && c.deviation <= c.spec.upper;
  return c;
}
CharacteristicResult size(double deviation, double tol) {
  CharacteristicResult c;
  c.spec.name = "length";
  c.spec.kind = CharacteristicKind::Distance;
  c.spec.lower = -tol;
  c.spec.upper = tol;
  c.nominal = 120;
  c.actual = 120 + deviation;
  c.deviation = deviation;
  c.in_tolerance = c.deviation >= c.spec.lower && c.deviation <= c.spec.upper;
  return c;
}
}  // namespace

TEST_CASE("inspection reports print enough decimals to show the verdict, four when that suffices") {
  CHECK(decimals_for(zone(0.00002, 0.01)) == 4);
  CHECK(decimals_for(size(-0.0000213, 0.05)) == 4);
  // A zone of 0.000104 against 0.0001 read "0.0001 <= 0.0001 OUT"; now the figures differ.
  const auto out = zone(0.000104, 0.0001);
  REQUIRE_FALSE(out.in_tolerance);
  CHECK(decimals_for(out) == 6);
  CHECK(tolerance_text(out) == "<= 0.000100");
  // Just outside a size tolerance, and just inside it.
  CHECK(decimals_for(size(0.05004, 0.05)) == 5);
  CHECK(tolerance_text(size(0.05004, 0.05)) == "-0.05000/+0.05000");
  CHECK(decimals_for(size(0.0499996, 0.05)) == 4);   // prints +0.0500 <= +0.0500: ok, and it is
  CHECK(decimals_for(size(-0.0500004, 0.05)) == 7);  // OUT by 0.4 nm: shown at the 7th decimal
  CHECK(verdict_text(size(-0.0500004, 0.05)) == "OUT");
}

TEST_CASE("report numbers: a value that prints as zero has no minus sign, a signed format gives it +") {
  using imess::messcap::fixed_text;
  using imess::messcap::number_text;
  CHECK(fixed_text(-0.00001, 4) == "0.0000");
  CHECK(fixed_text(-0.00001, 4, true) == "+0.0000");
  CHECK(fixed_text(-0.0, 2) == "0.00");
  CHECK(fixed_text(-0.00006, 4) == "-0.0001");  // a real negative value keeps its sign
  CHECK(fixed_text(0.00001, 4, true) == "+0.0000");
  CHECK(number_text(-0.00004, "%.4f") == "0.0000");
  CHECK(number_text(-0.00004, "%+.4f") == "+0.0000");
  CHECK(number_text(-0.4, "%.0f") == "0");
  CHECK(number_text(-12.5, "%.1f") == "-12.5");
  CHECK(number_text(-1e-9, "%.3f mm") == "0.000 mm");
}

TEST_CASE("labels are placed inside their area and never over one another") {
  const LabelRect area{46, 10, 304, 254};
  std::vector<LabelRequest> crowd;
  for (int i = 0; i < 12; ++i)  // twelve features named at nearly one point, some near the edge
    crowd.push_back({"feature_" + std::to_string(i), 60.0 + (i % 3), 20.0 + (i % 2), 1, -1});
  crowd.push_back({"right", 349, 100, 1, 0});  // wants to go right, out of the picture
  const std::vector<LabelRect> points{{55, 15, 7, 7}, {70, 30, 7, 7}};
  const auto placed = place_labels(crowd, area, points, 10);
  REQUIRE(placed.size() == crowd.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    INFO(placed[i].text);
    CHECK(placed[i].box.inside(area));
    CHECK(placed[i].box.w >= label_text_width(placed[i].text, 10));
    for (std::size_t j = i + 1; j < placed.size(); ++j) CHECK_FALSE(placed[i].box.overlaps(placed[j].box));
  }
  // A lone label sits next to its anchor, on the side it prefers (above and right, in SVG's y down).
  const auto one = place_labels({{"bore", 200, 150, 1, -1}}, area, {}, 10);
  CHECK(one[0].box.x > 200 - 1);
  CHECK(one[0].box.y + one[0].box.h < 150 + 1);
  CHECK_FALSE(one[0].far);
}
