// messcap's QIF writer from the inside: the saved report's reader names what is wrong by key,
// text is escaped and numbers are written exactly, ids are unique and every reference points at an
// element (tests/clients/qif/test_qif.py validates whole documents against the QIF schemas).
#include <catch2/catch.hpp>

#include <map>
#include <regex>
#include <set>

#include "qif_document.hpp"
#include "qif_xml.hpp"
#include "saved_inspection.hpp"

using namespace imess::messcap;

namespace {

// A small report: a plane and a circle (fit failed), a flatness and a diameter not evaluated.
std::string report(const std::string& replace_from = "", const std::string& replace_to = "") {
  std::string text = R"({"part": "plate", "plan": "plate.plan.json", "measured": "points from p.txt",
    "time": "2026-11-29T10:00:00Z", "operator": "Ann & Bob",
    "alignment": {"from": "placement"},
    "features": [
      {"name": "top", "points": 3, "nominal": {"type": "plane", "point": [0, 0, 10], "normal": [0, 0, 1]},
       "actual": {"type": "plane", "point": [0, 0, 10.001], "normal": [0, 0, 1]}, "compensated": false,
       "form": 0.002, "rms": 0.001},
      {"name": "hole", "points": 2, "nominal": {"type": "circle", "center": [5, 5, 10], "normal": [0, 0, 1],
       "diameter": 4, "inner": true}, "error": "too few points"}],
    "characteristics": [
      {"name": "top flatness", "type": "flatness", "feature": "top", "unit": "mm", "zone": true, "lower": 0,
       "upper": 0.01, "nominal": 0, "actual": 0.002, "deviation": 0.002, "in_tolerance": true},
      {"name": "hole <dia>", "type": "size", "feature": "hole", "unit": "mm", "zone": false, "lower": -0.1,
       "upper": 0.1, "error": "'hole' has no fit"}],
    "points": [{"feature": "top", "xyz": [1, 1, 10.001], "deviation": 0.001},
               {"feature": "top", "xyz": [9, 1, 10.002], "deviation": 0.002},
               {"feature": "top", "xyz": [9, 9, 10], "deviation": 0},
               {"feature": "hole", "xyz": [7, 5, 10], "deviation": 0},
               {"feature": "hole", "xyz": [5, 7, 10], "deviation": 0}]})";
  if (!replace_from.empty()) {
    const auto at = text.find(replace_from);
    REQUIRE(at != std::string::npos);
    text.replace(at, replace_from.size(), replace_to);
  }
  return text;
}

std::string error_of(const std::string& text) {
  try {
    (void)parse_saved_inspection(text, "r.json");
  } catch (const SavedInspectionError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("a saved inspection report is read whole, and a bad one named by key") {
  const auto s = parse_saved_inspection(report(), "r.json");
  CHECK(s.part == "plate");
  CHECK(s.operator_name == "Ann & Bob");
  REQUIRE(s.features.size() == 2);
  CHECK(s.features[0].actual);
  CHECK_FALSE(s.features[1].actual);
  CHECK(s.features[1].nominal.diameter == 4);
  REQUIRE(s.characteristics.size() == 2);
  CHECK(*s.characteristics[0].actual == 0.002);
  CHECK_FALSE(s.characteristics[1].actual);
  CHECK(s.points.size() == 5);

  CHECK(error_of("[1, 2]") == "r.json: (document): expected the JSON object messcap inspect --json writes");
  const std::string syntax = error_of("{\"part\": ");
  CHECK(syntax.rfind("r.json:", 0) == 0);
  CHECK(syntax.find("(expected a report of messcap inspect --json)") != std::string::npos);
  CHECK(error_of(report("\"part\": \"plate\",", "\"part\": \"plate\", \"part\": \"lid\",")).find("part") !=
        std::string::npos);  // a duplicate key
  CHECK(error_of(report("\"part\": \"plate\",", "")) == "r.json: part: missing");
  CHECK(error_of(report("\"actual\": 0.002", "\"actual\": \"0.002\"")) ==
        "r.json: characteristics[0].actual: expected a number");
  CHECK(error_of(report("\"type\": \"flatness\"", "\"type\": \"wobble\"")) ==
        "r.json: characteristics[0].type: 'wobble': expected size, position, distance, angle, flatness, roundness, "
        "cylindricity, sphericity, perpendicularity or parallelism");
  CHECK(error_of(report("\"feature\": \"top\", \"unit\"", "\"feature\": \"bottom\", \"unit\"")) ==
        "r.json: characteristics[0].feature: no feature 'bottom' in \"features\"");
  CHECK(error_of(report("\"name\": \"hole\"", "\"name\": \"top\"")) == "r.json: features[1].name: 'top' named twice");
  CHECK(error_of(report("[5, 5, 10], \"normal\": [0, 0, 1]", "[5, 5, 10], \"normal\": [0, 0, 2]")) ==
        "r.json: features[1].nominal.normal: expected a unit vector");
  CHECK(error_of(report("\"diameter\": 4", "\"diameter\": -4")) ==
        "r.json: features[1].nominal.diameter: expected a diameter above 0");
  CHECK(error_of(report("\"upper\": 0.01", "\"upper\": -0.01")) == "r.json: characteristics[0]: lower above upper");
  CHECK(error_of(report("\"xyz\": [1, 1, 10.001]", "\"xyz\": [1, 1]")) == "r.json: points[0].xyz: expected [x, y, z]");
  CHECK(error_of(report("\"alignment\": {\"from\": \"placement\"}",
                        "\"alignment\": {\"from\": \"alignment\", \"datums\": [\"top\", \"top\", \"side\"]}")) ==
        "r.json: alignment.datums[2]: no feature 'side' in \"features\"");
}

TEST_CASE("QIF text: escaped, numbers exact and short") {
  CHECK(xml_escaped("a<b & \"c\" 'd'>") == "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
  CHECK(xml_escaped(std::string("bell\x07") + "tab\t") == "bell\xEF\xBF\xBDtab\t");
  CHECK(qif_number(120.1) == "120.1");
  CHECK(qif_number(-0.0000001) == "0");
  CHECK(qif_number(30.0000004) == "30");
  CHECK(qif_number(0.000104, 9) == "0.000104");
  CHECK(qif_number(-2.5) == "-2.5");
  CHECK(qif_vector({1, 0, -1e-12}, 9) == "1 0 0");
}

TEST_CASE("a QIF document: unique ids, every reference resolves, the failed fit and the unevaluated characteristic said") {
  const std::string doc = qif_document({{parse_saved_inspection(report(), "r.json"), "r.json"}}, "2026-11-29T10:00:01Z",
                                       "00000000-0000-4000-8000-000000000000");
  std::set<unsigned> ids;
  const std::regex id_attr(R"re( id="(\d+)")re");
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), id_attr); it != std::sregex_iterator(); ++it)
    CHECK(ids.insert(static_cast<unsigned>(std::stoul((*it)[1]))).second);
  REQUIRE_FALSE(ids.empty());
  CHECK(doc.find("idMax=\"" + std::to_string(*ids.rbegin()) + "\"") != std::string::npos);
  const std::regex reference(R"re(<(\w*Id)>(\d+)</\w*Id>)re");
  std::size_t references = 0;
  for (auto it = std::sregex_iterator(doc.begin(), doc.end(), reference); it != std::sregex_iterator(); ++it, ++references) {
    INFO((*it)[0]);
    CHECK(ids.count(static_cast<unsigned>(std::stoul((*it)[2]))) == 1);
  }
  CHECK(references > 10);
  CHECK(doc.find("<Name>Ann &amp; Bob</Name>") != std::string::npos);
  CHECK(doc.find("<Name>hole &lt;dia&gt;</Name>") != std::string::npos);
  CHECK(doc.find("<CharacteristicStatusEnum>INDETERMINATE</CharacteristicStatusEnum>") != std::string::npos);
  CHECK(doc.find("<Description>not evaluated: &apos;hole&apos; has no fit</Description>") != std::string::npos);
  CHECK(doc.find("<InspectionStatusEnum>NOT_CALCULATED</InspectionStatusEnum>") != std::string::npos);
  CHECK(doc.find("<QPId>00000000-0000-4000-8000-000000000000</QPId>") != std::string::npos);

  // Two runs of different plans do not share a document.
  const auto other = parse_saved_inspection(report("\"part\": \"plate\"", "\"part\": \"lid\""), "o.json");
  CHECK_THROWS_WITH(qif_document({{parse_saved_inspection(report(), "r.json"), "r.json"}, {other, "o.json"}}),
                    "o.json is not a run of the plan of r.json: part 'lid', not 'plate'; one QIF document holds runs "
                    "of one plan");
  CHECK(std::regex_match(new_qpid(), std::regex("[0-9a-f]{8}-[0-9a-f]{4}-4[0-9a-f]{3}-[89ab][0-9a-f]{3}-[0-9a-f]{12}")));
}
