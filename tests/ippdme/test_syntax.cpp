// The value grammar: numbers, strings, names, event tags, nested calls and the space rules.
#include <catch2/catch.hpp>

#include <limits>
#include <string>

#include "imess/ippdme/syntax.hpp"

using namespace imess::ippdme;

namespace {
Value call(std::string_view text) {
  auto r = parse_call(text);
  INFO(text);
  REQUIRE(r.call);
  return *r.call;
}
ErrorCode syntax_error(std::string_view text) {
  auto r = parse_call(text);
  INFO(text);
  REQUIRE_FALSE(r.call);
  REQUIRE(r.error);
  return r.error->code;
}
}  // namespace

TEST_CASE("ippdme numbers: the spec's forms") {
  CHECK(parse_number_token("7.") == 7.0);
  CHECK(parse_number_token(".5") == 0.5);
  CHECK(parse_number_token("-0.129") == -0.129);
  CHECK(parse_number_token("1.003E01") == Approx(10.03));
  CHECK(parse_number_token("+1.245E01") == Approx(12.45));
  CHECK(parse_number_token("-.77") == -0.77);
  CHECK(parse_number_token("1e5") == 1e5);
  CHECK(parse_number_token("1e-5") == 1e-5);
  CHECK(parse_number_token("1E+123") == 1e123);
  CHECK(parse_number_token("1234567890123456") == 1234567890123456.0);  // 16 digits
  CHECK(parse_number_token("0.000000000000001") == 1e-15);              // 16 digits
  for (const char* bad : {"", "+", "-", ".", "e5", "1e", "1e+", "1e1234", "1.2.3", "--1", "+-1", "1-", "12345678901234567",
                          "0.0000000000000001", "1e5.0", "0x10", "1,5", " 1", "inf", "nan", "1 "}) {
    INFO(bad);
    CHECK_FALSE(parse_number_token(bad));
  }
  CHECK_FALSE(parse_number_token("1e999"));  // a number, but beyond a double
  CHECK(parse_number_token("1e-999") == 0.0);
}

TEST_CASE("ippdme names: letters and digits from a letter, dotted parts") {
  for (const char* good : {"X", "Tool", "Tool.PtMeasPar.Speed.Max", "XX.Cmd", "A1.B2", "IJK"}) CHECK(is_name(good));
  for (const char* bad : {"", "1X", ".X", "X.", "X..Y", "X.1", "X_Y", "X-Y", "X Y"}) {
    INFO(bad);
    CHECK_FALSE(is_name(bad));
  }
}

TEST_CASE("ippdme calls: nested calls, strings, words, event tags") {
  auto v = call("PtMeas(X(1), Y(2), Z(3), IJK(0,0,1))");
  CHECK(v.kind == ValueKind::Call);
  CHECK(v.text == "PtMeas");
  REQUIRE(v.args.size() == 4);
  CHECK(v.args[0].text == "X");
  CHECK(v.args[0].args.at(0).number == 1);
  CHECK(v.args[3].text == "IJK");
  CHECK(v.args[3].args.size() == 3);
  CHECK(v.args[3].args[2].number == 1);

  auto g = call("Get(X(), Y(), Z())");
  REQUIRE(g.args.size() == 3);
  CHECK(g.args[2].kind == ValueKind::Call);
  CHECK(g.args[2].args.empty());

  auto p = call("GetProp(Tool.PtMeasPar.Speed())");
  CHECK(p.args.at(0).text == "Tool.PtMeasPar.Speed");

  auto s = call("ChangeTool(\"Probe 1, long (A)\")");
  CHECK(s.args.at(0).kind == ValueKind::String);
  CHECK(s.args.at(0).text == "Probe 1, long (A)");

  auto w = call("SetCoordSystem(PartCsy)");
  CHECK(w.args.at(0).kind == ValueKind::Word);
  auto e = call("StopDaemon(E0005)");
  CHECK(e.args.at(0).kind == ValueKind::EventTag);
  CHECK(call("StopDaemon(E00051)").args.at(0).kind == ValueKind::Word);
  CHECK(call("Vendor.Cmd()").text == "Vendor.Cmd");
  CHECK(call("A(\"\")").args.at(0).text.empty());
}

TEST_CASE("ippdme spaces: allowed around commas, around ( and before ), nowhere else") {
  const Value ref = call("GoTo(X(1),Y(2))");
  for (const char* ok : {"GoTo(X(1), Y(2))", "GoTo( X(1) , Y(2) )", "GoTo (X (1),Y ( 2 ))", "GoTo(X(1)  ,   Y(2)   )",
                         "GoTo(  X(  1  )  ,  Y(2))"}) {
    INFO(ok);
    auto v = call(ok);
    CHECK(v.args.size() == 2);
    CHECK(v.args[1].args.at(0).number == 2);
  }
  CHECK(ref.args.size() == 2);
  CHECK(call("Home( )").args.empty());
  CHECK(call("Home ()").args.empty());
  // The line itself is garbled (a token that cannot be read, a space inside a name or a
  // number, the line ending inside the call, something after it): 0008.
  for (const char* bad : {" GoTo(X(1))", "GoTo(X(1)) ", "Go To(X(1))", "GoTo(X(- 1))", "Tool. Name()", "GoTo(X(1))x",
                          "GoTo", "GoTo(", "GoTo(X(1)", "GoTo(X(1)))", "GoTo(X(1),", "A(\"x)", "(1)", "1(2)",
                          "\"A\"()", "A(#)", ""}) {
    INFO(bad);
    CHECK(syntax_error(bad) == ErrorCode::ProtocolError);
  }
  // Readable tokens that make no argument list (a missing argument, two values without a
  // comma between them): the call's arguments are wrong, 0502 (the NIST server's answer).
  for (const char* bad : {"GoTo(X(1 2))", "GoTo(X(1. 5))", "Get(Tool .A())", "GoTo(,)", "GoTo(X(1),)", "GoTo(,X(1))",
                          "GoTo(X(1)Y(2))", "A(\"x\"y)", "GoTo(X(1,)", "GoTo(X(1,))", "GoTo(X(,1))"}) {
    INFO(bad);
    CHECK(syntax_error(bad) == ErrorCode::IncorrectArguments);
  }
  CHECK(syntax_error("GoTo(X(1e999))") == ErrorCode::IncorrectArguments);
}

TEST_CASE("ippdme calls: nesting is bounded") {
  std::string deep = "A(";
  for (std::size_t i = 1; i < kMaxNesting; ++i) deep += "B(";
  deep += std::string(kMaxNesting, ')');
  CHECK(parse_call(deep).call);
  std::string deeper = "A" + std::string(50000, 'B') + "(";
  for (int i = 0; i < 50000; ++i) deeper += "B(";
  CHECK(syntax_error(deeper) == ErrorCode::ProtocolError);
  std::string too_deep = "A(";
  for (std::size_t i = 0; i < kMaxNesting; ++i) too_deep += "B(";
  too_deep += std::string(kMaxNesting + 1, ')');
  CHECK(syntax_error(too_deep) == ErrorCode::ProtocolError);
}

TEST_CASE("ippdme writing values: \", \" between arguments, shortest numbers within 16 digits") {
  CHECK(format_value(Value::call("Get", {Value::call("X"), Value::call("Y"), Value::call("Z")})) == "Get(X(), Y(), Z())");
  CHECK(format_values({Value::call("X", {Value::of_fixed(150, 4)}), Value::call("Y", {Value::of_fixed(-20, 4)})}) ==
        "X(150.0000), Y(-20.0000)");
  CHECK(format_value(Value::of_string("a\"b")) == "\"a'b\"");
  CHECK(format_number(0.1) == "0.1");
  CHECK(format_number(-0.0) == "0");
  CHECK(format_number(1e300) == "1e+300");
  CHECK(format_number(1.0 / 3.0) == "3.333333333333333e-01");  // 0.3333333333333333 has 17 digits
  CHECK(parse_number_token(format_number(1.0 / 3.0)) == 1.0 / 3.0);
  CHECK(format_number(0.1 + 0.2) == "0.3");  // 17 significant digits either way: rounded to 15
  CHECK(format_number(0.001234567890123456) == "1.234567890123456e-03");
  CHECK(parse_number_token(format_number(0.001234567890123456)) == 0.001234567890123456);
  CHECK(format_number(std::numeric_limits<double>::infinity()) == "0");
  CHECK(format_fixed(-0.00001, 4) == "0.0000");
  CHECK(format_value(Value::of_integer(-12)) == "-12");
}
