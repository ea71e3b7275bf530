// imess::jsontext, the strict JSON text reader every JSON reader shares: its refusals name the
// source and the key path, and say what is accepted; nothing escapes as a library exception.
#include <catch2/catch.hpp>

#include <string>

#include "imess/jsontext/strict_json.hpp"

using imess::jsontext::JsonTextError;
using imess::jsontext::Options;
using imess::jsontext::parse_strict;

namespace {
std::string error_of(const std::string& text, const Options& options = {}) {
  try {
    (void)parse_strict(text, "f.json", options);
  } catch (const JsonTextError& e) {
    return e.what();
  }
  return "(parsed)";
}
}  // namespace

TEST_CASE("strict JSON: a number beyond a double is refused with its key and the accepted range") {
  CHECK(error_of(R"({"offsets":[{"name":"G510","x":[1,1e309]}]})") ==
        "f.json: key 'offsets[0].x[1]' holds a number too large for a double ('1e309'); numbers from "
        "-1.7976931348623157e308 to 1.7976931348623157e308 are accepted");
  CHECK(error_of("[3999999999999999999999999999e999999999]").find("key '[0]' holds a number too large") != std::string::npos);
  CHECK(error_of("-1e400").rfind("f.json: the document holds a number too large for a double ('-1e400')", 0) == 0);
  CHECK(parse_strict("[1e-400, 1.7976931348623157e308]", "f.json")[0] == 0.0);  // underflow is zero
}

TEST_CASE("strict JSON: with overflow_as_text the number becomes its text for the key's reader") {
  Options o;
  o.overflow_as_text = true;
  const auto doc = parse_strict(R"({"a": [1e400, -2e999], "b": 1e400})", "f.json", o);
  CHECK(doc["a"][0] == "1e400");
  CHECK(doc["a"][1] == "-2e999");
  CHECK(doc["b"] == "1e400");
}

TEST_CASE("strict JSON: duplicate keys, depth, syntax and comments") {
  CHECK(error_of(R"({"a": {"b": 1, "b": 2}})") == "f.json: key 'a.b' appears twice in the same object; give each key once");
  Options shallow;
  shallow.max_depth = 2;
  shallow.depth_hint = "plans need 2";
  CHECK(error_of("[[[1]]]", shallow) == "f.json: '[0][0]' nests objects and arrays deeper than 2 levels; plans need 2");
  CHECK(error_of(std::string(100000, '[')).find("deeper than 32 levels") != std::string::npos);
  CHECK(error_of("{\"a\": }").rfind("f.json: not valid JSON at line 1, column 7: ", 0) == 0);
  CHECK(error_of("// c\n{}").rfind("f.json: not valid JSON", 0) == 0);
  Options comments;
  comments.comments = true;
  CHECK(parse_strict("// c\n{\"a\": 1}", "f.json", comments)["a"] == 1);
}
