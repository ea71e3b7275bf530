// Seeded random programs in each language: the motion items' targets match an independent
// accumulation of the words, and the planner accepts every request the translators emit.
#include <catch2/catch.hpp>

#include <numbers>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "imess/planner/planner.hpp"
#include "imess/programs/gcode.hpp"
#include "imess/programs/hpgl.hpp"
#include "imess/programs/mrm.hpp"
#include "program_text.hpp"

using namespace imess::programs;
using imess::planner::Pose;

namespace {

// A value printed with 4 decimals and the number the text stands for.
double printed(double v, std::string& text) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  text = buf;
  return std::stod(text);
}

// Every motion target of `t` in order.
std::vector<Pose> targets(const Translation& t) {
  std::vector<Pose> out;
  for (const auto& it : t.items) {
    if (const auto* l = std::get_if<imess::planner::Line>(&it.step)) out.push_back(l->target);
    if (const auto* a = std::get_if<imess::planner::Arc>(&it.step)) out.push_back(a->target);
  }
  return out;
}

void check_targets(const std::vector<Pose>& got, const std::vector<Pose>& want, int axes) {
  REQUIRE(got.size() == want.size());
  for (std::size_t k = 0; k < got.size(); ++k)
    for (int i = 0; i < axes; ++i) {
      INFO("move " << k << " axis " << i);
      CHECK(got[k][i] == Approx(want[k][i]).margin(1e-9));
    }
}

void check_planner_accepts(const Translation& t, const imess::planner::Machine& m, const Pose& start) {
  imess::planner::Planner p(m);
  p.set_position(start);
  for (const auto& it : t.items) {
    imess::planner::AppendResult r;
    std::visit(
        [&](const auto& x) {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_constructible_v<imess::planner::Request, T>) r = p.append(x);
        },
        it.step);
    INFO(describe(it, m) << ": " << describe(r, m));
    REQUIRE(r.ok());
    while (p.ready()) {
      imess::planner::PlannedSegment s;
      p.take(s);
    }
  }
}
}  // namespace

TEST_CASE("properties: random G-code (G0/G1/G2/G3, G90/G91, G20/G21, G54/G55) ends where the words add up") {
  GcodeOptions o;
  o.machine = imess::planner::make_machine("XYZ", -1e6, 1e6, 100, 1000);
  o.work_offsets[0] = {1, 2, 3};
  o.work_offsets[1] = {-5, 10, 0.5};
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coord(-50, 50);
    std::uniform_int_distribution<int> pick(0, 99);
    Pose pos = o.start;
    bool absolute = true, inches = false;
    int coord_sys = 0;
    std::string program = "F300\n";
    std::vector<Pose> want;
    for (int n = 0; n < 60; ++n) {
      std::string line;
      const int r = pick(rng);
      if (r < 8) { absolute = !absolute; line += absolute ? "G90 " : "G91 "; }
      else if (r < 14) { inches = !inches; line += inches ? "G20 " : "G21 "; }
      else if (r < 18) { coord_sys = 1 - coord_sys; line += coord_sys ? "G55 " : "G54 "; }
      const double unit = inches ? 25.4 : 1.0;
      const auto& off = o.work_offsets[static_cast<std::size_t>(coord_sys)];
      const int kind = pick(rng);
      if (kind < 60) {  // straight move, random axes
        line += kind < 25 ? "G0" : "G1";
        Pose t = pos;
        bool named = false;
        for (int i = 0; i < 3; ++i) {
          if (pick(rng) < 50 || (i == 2 && !named)) {  // at least one axis word
            named = true;
            std::string text;
            const double v = printed(coord(rng) / unit, text);
            line += std::string(" ") + "XYZ"[i] + text;
            t[i] = absolute ? v * unit + off[i] : pos[i] + v * unit;
          }
        }
        want.push_back(t);
        pos = t;
      } else {  // a quarter arc in XY by I J, sometimes a helix in Z
        const bool ccw = kind % 2 == 0;
        std::string ti, tj, tx, ty, tz;
        const double i_off = printed(coord(rng) / unit, ti), j_off = printed(coord(rng) / unit, tj);
        if (std::hypot(i_off, j_off) * unit < 1) continue;
        const double cx = pos[0] + i_off * unit, cy = pos[1] + j_off * unit;
        const double a0 = std::atan2(pos[1] - cy, pos[0] - cx) + (ccw ? std::numbers::pi / 2 : -std::numbers::pi / 2);
        const double rr = std::hypot(i_off, j_off) * unit;
        Pose t = pos;
        const double ex = printed(((absolute ? cx + rr * std::cos(a0) - off[0] : rr * std::cos(a0) + cx - pos[0])) / unit, tx);
        const double ey = printed(((absolute ? cy + rr * std::sin(a0) - off[1] : rr * std::sin(a0) + cy - pos[1])) / unit, ty);
        t[0] = absolute ? ex * unit + off[0] : pos[0] + ex * unit;
        t[1] = absolute ? ey * unit + off[1] : pos[1] + ey * unit;
        line += std::string(ccw ? "G3" : "G2") + " X" + tx + " Y" + ty + " I" + ti + " J" + tj;
        if (pick(rng) < 40) {
          const double z = printed(coord(rng) / unit / 5, tz);
          line += " Z" + tz;
          t[2] = absolute ? z * unit + off[2] : pos[2] + z * unit;
        }
        want.push_back(t);
        pos = t;
      }
      program += line + "\n";
    }
    INFO("seed " << seed << "\n" << program);
    const auto t = translate_gcode(program, o);
    INFO(t.error.message());
    REQUIRE(t.ok);
    check_targets(targets(t), want, 3);
    check_planner_accepts(t, o.machine, o.start);
  }
}

TEST_CASE("properties: random HPGL (PU/PD, PA/PR) ends where the plotter units add up") {
  HpglOptions o;
  o.machine = imess::planner::make_machine("XYZ", -1e6, 1e6, 100, 1000);
  o.origin_x = 10;
  o.origin_y = -20;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> coord(-4000, 4000), pick(0, 99);
    std::string program = "IN;";
    std::vector<Pose> want{Pose{0, 0, o.pen_up_z}};
    double px = (0 - o.origin_x) * 40, py = (0 - o.origin_y) * 40, z = o.pen_up_z;
    bool relative = false, down = false;
    for (int n = 0; n < 60; ++n) {
      const int r = pick(rng);
      std::string ins;
      if (r < 20) {
        ins = down ? "PU" : "PD";
        down = !down;
        z = down ? o.pen_down_z : o.pen_up_z;
        want.push_back(Pose{o.origin_x + px / 40, o.origin_y + py / 40, z});
      } else {
        if (r < 40) relative = !relative;
        ins = relative ? "PR" : "PA";
      }
      const int pairs = pick(rng) % 3;
      for (int k = 0; k < pairs; ++k) {
        const int x = coord(rng), y = coord(rng);
        ins += (k ? "," : "") + std::to_string(x) + "," + std::to_string(y);
        px = relative ? px + x : x;
        py = relative ? py + y : y;
        want.push_back(Pose{o.origin_x + px / 40, o.origin_y + py / 40, z});
      }
      program += ins + ";";
      if (pick(rng) < 10) program += "\n";
    }
    INFO("seed " << seed << "\n" << program);
    const auto t = translate_hpgl(program, o);
    INFO(t.error.message());
    REQUIRE(t.ok);
    check_targets(targets(t), want, 3);
    check_planner_accepts(t, o.machine, o.start);
  }
}

TEST_CASE("properties: random MRM programs end at the sum of their moves, gripper as last set") {
  MrmOptions o;
  o.machine = imess::planner::make_machine("XYCAB", -1e6, 1e6, 100, 1000);
  // Word k moves machine axis k: X, Y, then A B C the rotary axes C A B in the machine's order.
  const char letters[] = {'X', 'Y', 'A', 'B', 'C'};
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> value(-30000, 30000), pick(0, 99);
    std::string program = "F1200\nS600\n";
    Pose sum{};
    double gripper = -1;
    int n_line = 2;
    for (int n = 0; n < 80; ++n) {
      const int r = pick(rng);
      std::string word;
      if (r < 10) {
        gripper = r < 5 ? 1 : 0;
        word = r < 5 ? "M03" : "M04";
      } else if (r < 15) {
        word = "F" + std::to_string(100 + pick(rng) * 10);
      } else {
        const int k = r % 5;
        const int v = value(rng);
        word = std::string(1, letters[k]) + std::to_string(v);
        sum[k] += v / 10.0;
      }
      ++n_line;
      program += (pick(rng) < 50 ? "N" + std::to_string(n_line) + " " : std::string()) + word + "\n";
    }
    program += "M02\n";
    INFO("seed " << seed << "\n" << program);
    const auto t = translate_mrm(program, o);
    INFO(t.error.message());
    REQUIRE(t.ok);
    const Pose end = end_pose(t.items, o.start);
    for (int i = 0; i < 5; ++i) CHECK(end[i] == Approx(sum[i]).margin(1e-9));
    double last = -1;
    for (const auto& it : t.items)
      if (const auto* out = std::get_if<imess::planner::SetOutput>(&it.step)) last = out->value;
    CHECK(last == gripper);
    CHECK(std::holds_alternative<End>(t.items.back().step));
    check_planner_accepts(t, o.machine, o.start);
  }
}
