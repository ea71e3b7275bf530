// HPGL: a worked plot compared item by item, pen by Z move or by output, plotter units,
// origin, separators and every error with its line:column.
#include <catch2/catch.hpp>

#include "imess/programs/hpgl.hpp"
#include "program_text.hpp"

using namespace imess::programs;
using namespace imess::programs::test;

namespace {
Lines hpgl(const char* text, const HpglOptions& o = {}) { return lines(translate_hpgl(text, o), o.machine); }
std::string hpgl_err(const char* text, const HpglOptions& o = {}) { return error_text(translate_hpgl(text, o)); }
}  // namespace

TEST_CASE("hpgl: worked plot — pen by Z, 40 units per mm, PA/PR, VS in cm/s, SP0 lifts") {
  const char* plot =
      "IN;SP1;\n"
      "PU0,0;\n"
      "PD400,0,400,400;\n"
      "PU;PA800,800;PR40,-40;\n"
      "VS5;PD;PR-40 0;\n"
      "SP0;\n";
  CHECK(hpgl(plot) == Lines{"1 LINE rapid X0 Y0 Z5 F100", "2 LINE rapid X0 Y0 Z5 F100", "3 LINE X0 Y0 Z0 F10",
                           "3 LINE X10 Y0 Z0 F20", "3 LINE X10 Y10 Z0 F20", "4 LINE rapid X10 Y10 Z5 F100",
                           "4 LINE rapid X20 Y20 Z5 F100", "4 LINE rapid X21 Y19 Z5 F100", "5 LINE X21 Y19 Z0 F10",
                           "5 LINE X20 Y19 Z0 F50", "6 LINE rapid X20 Y19 Z5 F100"});
}

TEST_CASE("hpgl: pen by a digital output — an unknown pen is lifted before the first move") {
  HpglOptions o;
  o.pen = HpglOptions::Pen::Output;
  o.pen_output = 7;
  CHECK(hpgl("PU;PD100,100;PU;", o) == Lines{"1 OUT 7=0", "1 OUT 7=1", "1 LINE X2.5 Y2.5 Z0 F20", "1 OUT 7=0"});
  CHECK(hpgl("PA40,40") == Lines{"1 LINE rapid X0 Y0 Z5 F100", "1 LINE rapid X1 Y1 Z5 F100"});
}

TEST_CASE("hpgl: origin, start pose, separators, lowercase, no terminators, VS reset") {
  HpglOptions o;
  o.origin_x = 100;
  o.origin_y = 50;
  o.start = {100, 50, 5};
  CHECK(hpgl("in pa 0 0 pd40,0pr 40 , 40;vs 1;pr-40,0;vs;pr0,-40", o) ==
        Lines{"1 LINE rapid X100 Y50 Z5 F100", "1 LINE rapid X100 Y50 Z5 F100", "1 LINE X100 Y50 Z0 F10",
              "1 LINE X101 Y50 Z0 F20", "1 LINE X102 Y51 Z0 F20", "1 LINE X101 Y51 Z0 F10",
              "1 LINE X101 Y50 Z0 F20"});
  // PR from the start pose: plotter position follows the machine's start.
  HpglOptions s;
  s.start = {2, 3, 5};
  CHECK(hpgl("PU;PR40,40", s) == Lines{"1 LINE rapid X2 Y3 Z5 F100", "1 LINE rapid X3 Y4 Z5 F100"});
}

TEST_CASE("hpgl errors: instructions, numbers, counts, ranges, travel") {
  const std::string ins = "IN SP PU PD PA PR VS";
  CHECK(hpgl_err("IN;CI100;") == "line 1:4: unsupported code: found CI, accepted " + ins);
  CHECK(hpgl_err("IN;\nPA0,0;\nLBtext;") == "line 3:1: unsupported code: found LB, accepted " + ins);
  CHECK(hpgl_err("1IN") == "line 1:1: bad character: found '1', accepted an instruction " + ins);
  CHECK(hpgl_err("I;") == "line 1:1: bad character: found ';', accepted an instruction " + ins);
  CHECK(hpgl_err("PA10,#") == "line 1:6: bad number: found '#', accepted numbers separated by ',' or spaces, ended by ';'");
  CHECK(hpgl_err("PA10,20,30;") == "line 1:9: value out of range: found PA with 3 coordinates, accepted x,y pairs (an even number of coordinates)");
  CHECK(hpgl_err("SP9") == "line 1:3: value out of range: found SP9, accepted SP0 ... SP8");
  CHECK(hpgl_err("SP1.5") == "line 1:3: value out of range: found SP1.5, accepted SP0 ... SP8");
  CHECK(hpgl_err("VS0") == "line 1:3: value out of range: found VS0, accepted VS > 0 (cm/s)");
  CHECK(hpgl_err("VS1,2") == "line 1:5: value out of range: found VS with 2 parameters, accepted VS or VS<cm/s>");
  CHECK(hpgl_err("IN1") == "line 1:3: value out of range: found IN with 1 parameters, accepted IN without parameters");
  CHECK(hpgl_err("PU;PA100000,0") == "line 1:6: out of travel: found X at 2500 (machine), accepted X within -1000 ... 1000");
}
