// messprog: check's figures for programs worked out by hand, errors as FILE:LINE:COL, the SVG
// plot's views, dashes, probe targets and sampled arcs, and run against a scripted messd
// (ProgramPeer) — what it sends, how it ends, Ctrl-C and a lost connection.
#include <catch2/catch.hpp>

#include <cmath>
#include <csignal>
#include <fstream>
#include <regex>

#include "child_process.hpp"
#include "fake_daemon.hpp"
#include "imess/client/usage_error.hpp"
#include "interrupts.hpp"
#include "progress_view.hpp"
#include "program_peer.hpp"
#include "run_session.hpp"
#include "upload.hpp"

using namespace imess::messprog;
using imess::test::ChildProcess;
using imess::test::client_binary;
using imess::test::ProgramPeer;
using imess::test::ProgramPeerScript;
using imess::test::read_file;
using imess::test::run_program;
using imess::test::TempDir;

namespace {

std::string write(const TempDir& dir, const std::string& name, const std::string& text) {
  const auto path = dir.file(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::vector<std::string> messprog(std::initializer_list<std::string> list) {
  std::vector<std::string> a{client_binary("messprog")};
  a.insert(a.end(), list.begin(), list.end());
  return a;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

// The text of <g id="ID" ...> up to its </g> (views hold no nested groups).
std::string group(const std::string& svg, const std::string& id) {
  const auto start = svg.find("<g id=\"" + id + "\"");
  if (start == std::string::npos) return {};
  const auto end = svg.find("</g>", start);
  return svg.substr(start, end - start);
}

// The (x, y) pairs of every <path class="CLASS" ... d="M x y L x y ..."> in `svg`, one list per path.
std::vector<std::vector<std::pair<double, double>>> paths(const std::string& svg, const std::string& cls) {
  std::vector<std::vector<std::pair<double, double>>> out;
  const std::regex path("<path class=\"" + cls + "\"[^>]* d=\"([^\"]*)\"");
  const std::regex point("([-0-9.]+) ([-0-9.]+)");
  for (std::sregex_iterator p(svg.begin(), svg.end(), path), end; p != end; ++p) {
    const std::string d = (*p)[1];
    out.emplace_back();
    for (std::sregex_iterator q(d.begin(), d.end(), point); q != end; ++q)
      out.back().emplace_back(std::stod((*q)[1]), std::stod((*q)[2]));
  }
  return out;
}

// 100 mm at 100 mm/s with 1000 mm/s² (the generic machine): 0.1 s up to speed over 5 mm,
// 90 mm at speed in 0.9 s, 0.1 s down: 1.1 s. Each dwell brings the path to rest, so the
// moves do not blend. The rapid back is the same 1.1 s (rapids run at the fastest axis'
// 100 mm/s). The probe: 10 mm at F600 = 10 mm/s, 0.01 s up and down over 0.05 mm each, 9.9 mm
// at speed in 0.99 s: 1.01 s. Total 1.1 + 0.5 + 1.1 + 0.25 + 1.01 = 3.96 s.
const std::string kByHand =
    "G21 G90\n"
    "G1 X100 F6000\n"
    "G4 P0.5\n"
    "G0 X0\n"
    "G4 P0.25\n"
    "G38.2 Z-10 F600\n"
    "M2\n";

}  // namespace

TEST_CASE("messprog check: lines, blocks, segments, length split, time and box of a program worked out by hand") {
  TempDir dir;
  const auto file = write(dir, "byhand.nc", kByHand);
  const auto r = run_program(messprog({"check", file}));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK_THAT(r.out, Catch::StartsWith(file + ": ok (gcode)\n"));
  // 7 lines; 6 items (the G21 G90 line makes none, M2 is the End item); 5 segments: 3 moves, 2 dwells
  CHECK_THAT(r.out, Catch::Contains("lines 7, blocks 6, segments 5\n"));
  CHECK_THAT(r.out, Catch::Contains("path length 210.000 mm: feed 100.000, rapid 100.000, probe 10.000\n"));
  CHECK_THAT(r.out, Catch::Contains("estimated time 3.96 s (the planner's estimate"));
  CHECK_THAT(r.out, Catch::Contains("machine: axes XYZ, travel -1000..1000, 100 mm/s and 1000 mm/s² per axis"));
  CHECK_THAT(r.out, Catch::Contains("  X        0.000 ..      100.000 mm\n"));
  CHECK_THAT(r.out, Catch::Contains("  Y        0.000 ..        0.000 mm\n"));
  CHECK_THAT(r.out, Catch::Contains("  Z      -10.000 ..        0.000 mm\n"));
}

TEST_CASE("messprog check: an arc's box is its circle, and a long program's time also reads as h:mm:ss") {
  TempDir dir;
  // A full circle of radius 10 around (0, 0) from (10, 0), 20 times (P20): 20 · 2π · 10 mm at
  // 10 mm/s ≈ 125.7 s, well over a minute.
  const auto file = write(dir, "circle.ngc", "G1 X10 F600\nG2 I-10 P20\n");
  const auto r = run_program(messprog({"check", file}));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("  X      -10.000 ..       10.000 mm\n"));
  CHECK_THAT(r.out, Catch::Contains("  Y      -10.000 ..       10.000 mm\n"));
  CHECK_THAT(r.out, Catch::Contains("path length 1266.637 mm: feed 1266.637"));  // 10 + 20 · 20π
  CHECK_THAT(r.out, Catch::Matches("[\\s\\S]*estimated time 12[67]\\.[0-9]{2} s \\(0:02:0[67]\\)[\\s\\S]*"));
}

TEST_CASE("messprog check: MRM on the arm's generic machine XYCUV, A B C turning its rotary joints C U V in order") {
  TempDir dir;
  const auto file = write(dir, "arm.mrm", "N1 F1000\nN2 X5000\nN3 S600\nN4 A900\nN5 C-450\nN6 M02\n");
  const auto r = run_program(messprog({"check", file}));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("machine: axes XYCUV") && Catch::Contains("(degrees for C U V)"));
  CHECK_THAT(r.out, Catch::Contains("  X        0.000 ..      500.000 mm\n"));
  CHECK_THAT(r.out, Catch::Contains("  C        0.000 ..       90.000 deg\n"));   // A900
  CHECK_THAT(r.out, Catch::Contains("  V      -45.000 ..        0.000 deg\n"));   // C-450
}

TEST_CASE("messprog check: a program error is FILE:LINE:COL: kind: found ..., accepted ... and exit 1") {
  TempDir dir;
  const auto bad = write(dir, "bad.nc", "G0 X1\nG1 X2 #5\n");
  auto r = run_program(messprog({"check", bad}));
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK_THAT(r.err, Catch::StartsWith(bad + ":2:7: bad character: found '#', accepted words N G M"));

  // The generic machine's travel: X100 leaves -50..50, a translation refusal with its column.
  const auto wide = write(dir, "wide.nc", "G21\nG0 X10\nG0 X100\n");
  r = run_program(messprog({"check", wide, "--travel", "-50:50"}));
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::StartsWith(wide + ":3:4: out of travel: found X at 100") && Catch::Contains("-50"));

  // An arc bulging out of the travel though both its ends lie inside: the planner's refusal.
  // (centre 0, 10, radius 40: the ends at X ±40 lie inside ±45, the top at Y 50 does not)
  const auto arc = write(dir, "arc.nc", "G1 X40 Y10 F600\nG3 X-40 Y10 I-40 J0\n");
  r = run_program(messprog({"check", arc, "--travel", "-45:45"}));
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::StartsWith(arc + ":2:1: ") && Catch::Contains("axis Y"));
}

TEST_CASE("messprog check: an unreadable file is exit 1 naming it — bad arguments are exit 2 naming them") {
  TempDir dir;
  auto r = run_program(messprog({"check", dir.file("missing.nc")}));
  CHECK(r.status == 1);
  CHECK(r.err == "messprog: cannot read '" + dir.file("missing.nc") + "': no such file or directory\n");

  const auto txt = write(dir, "part.txt", "G0 X1\n");
  r = run_program(messprog({"check", txt}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("unknown extension '.txt'") && Catch::Contains(".nc .ngc .gcode .tap") &&
                        Catch::Contains("--lang gcode|hpgl|mrm") && Catch::Contains("(try messprog --help)"));
  r = run_program(messprog({"check", txt, "--lang=gcode"}));  // the language named: fine
  CHECK(r.status == 0);
  r = run_program(messprog({"check", txt, "--lang", "basic"}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: --lang 'basic': accepted gcode, hpgl, mrm"));
  r = run_program(messprog({"check", txt, "--lang", "gcode", "--axes", "XYY"}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: --axes 'XYY': Y appears twice; accepted: 1 to 9 axis letters"));
  r = run_program(messprog({"check", txt, "--lang", "gcode", "--travel", "5:-5"}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: --travel '5:-5': MIN must be below MAX"));
  r = run_program(messprog({"check", txt, "--lang", "gcode", "--detached"}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: unknown option '--detached' for check; accepted: --canon, --config FILE, --from X,Y,Z, --lang L, --axes"));
  r = run_program(messprog({"check", txt, "other.nc", "--lang", "gcode"}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: unexpected argument 'other.nc'; check takes one program FILE"));
  r = run_program(messprog({"check"}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: check needs a program FILE"));
  const auto plt = write(dir, "p.plt", "IN;PD40,40;");
  r = run_program(messprog({"check", plt, "--axes", "XZ"}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: --axes 'XZ': HPGL draws in X and Y"));
}

TEST_CASE("messprog plot: two views, dashed rapids, a target marker per G38.2 line in each view, a legend") {
  TempDir dir;
  const std::string program =
      "(pocket outline with arcs, then two probes)\n"
      "G21 G90 G17\n"
      "G0 Z5\n"
      "G0 X10 Y10\n"
      "G1 Z-1 F300\n"
      "G1 X60 F600\n"
      "G3 X80 Y30 I0 J20\n"
      "G1 Y60\n"
      "G3 X60 Y80 I-20 J0\n"
      "G1 X10\n"
      "G1 Y10\n"
      "G0 Z5\n"
      "G0 X40 Y40\n"
      "G38.2 Z-20 F100\n"
      "G0 Z5\n"
      "G0 X90 Y45\n"
      "G38.2 X110 F100\n"
      "G0 X90\n"
      "M2\n";
  const auto file = write(dir, "part.ngc", program);
  const auto svg_path = dir.file("part.svg");
  const auto r = run_program(messprog({"plot", file, "-o", svg_path}));
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("wrote " + svg_path + ": X-Y (top) and X-Z (front)") &&
                        Catch::Contains("2 probing moves"));
  const std::string svg = read_file(svg_path);
  CHECK_THAT(svg, Catch::StartsWith("<?xml") && Catch::EndsWith("</svg>\n"));
  CHECK(count(svg, "<g ") == count(svg, "</g>"));
  const auto probes = count(program, "G38.2");
  for (const char* id : {"view-xy", "view-xz"}) {
    INFO(id);
    const auto view = group(svg, id);
    REQUIRE_FALSE(view.empty());
    CHECK(count(view, "class=\"probe-target\"") == probes);
    CHECK(count(view, "<path class=\"probe\"") == probes);  // the probes do not follow each other
    const auto rapids = paths(view, "rapid");
    CHECK_FALSE(rapids.empty());
    CHECK(count(view, "<path class=\"rapid\"") == count(view, "stroke-dasharray"));  // every rapid dashed, nothing else
    CHECK(count(view, "<path class=\"feed\"") >= 1);
    CHECK_THAT(view, Catch::Contains("[mm]"));  // axis names with their unit
  }
  CHECK_THAT(group(svg, "view-xy"), Catch::Contains(">X-Y (top)<") && Catch::Contains("box: X 0.000 .. 110.000 mm, Y 0.000 .. 80.000 mm"));
  CHECK_THAT(group(svg, "view-xz"), Catch::Contains(">X-Z (front)<") && Catch::Contains("Z -20.000 .. 5.000 mm"));
  const auto legend = group(svg, "legend");
  CHECK_THAT(legend, Catch::Contains("feed move") && Catch::Contains("rapid") && Catch::Contains("probing move") &&
                         Catch::Contains("probe target"));
}

TEST_CASE("messprog plot: an arc is drawn as many points on its circle") {
  TempDir dir;
  const auto file = write(dir, "circle.nc", "G1 X10 F600\nG2 I-10\n");  // to (10, 0), then a full circle about 0, 0
  const auto svg_path = dir.file("circle.svg");
  REQUIRE(run_program(messprog({"plot", file, "-o", svg_path})).status == 0);
  const auto feeds = paths(group(read_file(svg_path), "view-xy"), "feed");
  REQUIRE(feeds.size() == 1);
  auto points = feeds[0];
  points.erase(points.begin());  // (0, 0), where the line to the circle starts
  CHECK(points.size() >= 360);   // a point every degree or closer
  double lo_x = 1e9, hi_x = -1e9, lo_y = 1e9, hi_y = -1e9;
  for (auto [x, y] : points) {
    lo_x = std::min(lo_x, x), hi_x = std::max(hi_x, x), lo_y = std::min(lo_y, y), hi_y = std::max(hi_y, y);
  }
  const double cx = (lo_x + hi_x) / 2, cy = (lo_y + hi_y) / 2, radius = (hi_x - lo_x) / 2;
  CHECK(hi_y - lo_y == Approx(hi_x - lo_x).margin(0.05));  // one scale for both directions
  CHECK(radius > 100);  // scaled to fill the panel
  for (auto [x, y] : points) CHECK(std::hypot(x - cx, y - cy) == Approx(radius).margin(0.03));
}

TEST_CASE("messprog check --canon: the motion as LinuxCNC's rs274 -g prints it, in program units") {
  TempDir dir;
  const auto file = write(dir, "canon.ngc", "%\nG20 G90\nG0 X1 Y2\nG1 Z-0.1 F10\nG2 X2 Y2 I0.5\nG38.2 Z-1\nG4 P0.5\nG91 G28 Z0\nM2\n%\n");
  const auto r = run_program(messprog({"check", "--canon", file}));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(r.out ==
        "USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
        "USE_LENGTH_UNITS(CANON_UNITS_INCHES)\n"
        "STRAIGHT_TRAVERSE(1.0000, 2.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
        "SET_FEED_RATE(10.0000)\n"
        "STRAIGHT_FEED(1.0000, 2.0000, -0.1000, 0.0000, 0.0000, 0.0000)\n"
        "ARC_FEED(2.0000, 2.0000, 1.5000, 2.0000, -1, -0.1000, 0.0000, 0.0000, 0.0000)\n"
        "STRAIGHT_PROBE(2.0000, 2.0000, -1.0000, 0.0000, 0.0000, 0.0000)\n"
        "DWELL(0.5000)\n"
        "STRAIGHT_TRAVERSE(2.0000, 2.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
        "PROGRAM_END()\n");
  const auto bad = run_program(messprog({"check", "--canon", write(dir, "bad.ngc", "G81 X1\n")}));
  CHECK(bad.status == 1);
  CHECK_THAT(bad.err, Catch::Contains("bad.ngc:1:1: unsupported code: found G81"));
}

TEST_CASE("messprog check: G28's move home counts as rapid, the codes accepted without effect are listed") {
  TempDir dir;
  const auto file = write(dir, "cam.ngc", "G17 G21 G40 G49 G80 G90 G94\nG64 P0.01\nG0 X10 Y20 Z30\n/G0 X500\nG91 G28 Z0\nG40\nM1\nM30\n");
  const auto r = run_program(messprog({"check", file}));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("path length 67.417 mm: feed 0.000, rapid 67.417, probe 0.000\n"));
  CHECK_THAT(r.out, Catch::Contains("accepted without effect, or skipped:\n"));
  CHECK_THAT(r.out, Catch::Contains("  G40 (line 1, 2 times): cutter radius compensation off: IMESS never compensates\n"));
  CHECK_THAT(r.out, Catch::Contains("  G64 (line 2): path blending"));
  CHECK_THAT(r.out, Catch::Contains("  / (line 4): block delete"));
  CHECK_THAT(r.out, Catch::Contains("  M1 (line 7): optional stop"));
  CHECK_THAT(r.out, Catch::Contains("  Z        0.000 ..       30.000 mm\n"));
}

TEST_CASE("messprog check and plot --from X,Y,Z: the machine starts there") {
  TempDir dir;
  const auto file = write(dir, "from.ngc", "G91 G0 X10\n");
  const auto r = run_program(messprog({"check", "--from", "430,330,100", file}));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("starting at 430 330 100"));
  CHECK_THAT(r.out, Catch::Contains("  X      430.000 ..      440.000 mm\n"));
  CHECK_THAT(r.out, Catch::Contains("path length 10.000 mm"));
  const auto bad = run_program(messprog({"check", "--from", "1,2", file}));
  CHECK(bad.status == 2);
  CHECK_THAT(bad.err, Catch::Contains("--from '1,2'; accepted X,Y,Z...: one number per axis of the machine (3)"));
  const auto out = run_program(messprog({"check", "--from=0,0,5000", file}));
  CHECK(out.status == 2);
  CHECK_THAT(out.err, Catch::Contains("Z outside its travel"));
  const auto svg = dir.file("from.svg");
  CHECK(run_program(messprog({"plot", file, "--from", "430,330,100", "-o", svg})).status == 0);
  CHECK_THAT(group(read_file(svg), "view-xy"), Catch::Contains("box: X 430.000 .. 440.000 mm"));
}

TEST_CASE("messprog plot: G28's move home is drawn dashed, as a rapid") {
  TempDir dir;
  const auto file = write(dir, "home.ngc", "G1 X10 Y10 Z10 F600\nG91 G28 Z0\n");
  const auto svg_path = dir.file("home.svg");
  REQUIRE(run_program(messprog({"plot", file, "-o", svg_path})).status == 0);
  const auto view = group(read_file(svg_path), "view-xz");
  CHECK(count(view, "<path class=\"rapid\"") == 1);
  CHECK(count(view, "<path class=\"feed\"") == 1);
}

TEST_CASE("messprog plot: a bad output name is exit 2, a program error exit 1 and no file") {
  TempDir dir;
  const auto file = write(dir, "p.nc", "G0 X1\n");
  auto r = run_program(messprog({"plot", file, "-o", dir.file("p.png")}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: -o '" + dir.file("p.png") + "': the plot is an SVG drawing; accepted: a file name ending in .svg"));
  r = run_program(messprog({"plot", file}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: plot needs -o OUT.svg"));
  const auto bad = write(dir, "bad.nc", "G0 X1\nG81 X2\n");
  r = run_program(messprog({"plot", bad, "-o", dir.file("bad.svg")}));
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::StartsWith(bad + ":2:1: unsupported code: found G81"));
  CHECK_FALSE(imess::test::file_exists(dir.file("bad.svg")));
  r = run_program(messprog({"plot", file, "-o", dir.file("no/such/dir/p.svg")}));
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: cannot write '" + dir.file("no/such/dir/p.svg") + "'"));
}

TEST_CASE("messprog plot: the MRM arm's second view is C against X") {
  TempDir dir;
  const auto file = write(dir, "arm.mrm", "N1 F1000\nN2 X5000\nN3 S600\nN4 A-450\nN5 M02\n");
  const auto svg_path = dir.file("arm.svg");
  REQUIRE(run_program(messprog({"plot", file, "-o", svg_path})).status == 0);
  const auto svg = read_file(svg_path);
  CHECK_THAT(group(svg, "view-xy"), Catch::Contains("X-Y (top)"));
  CHECK_THAT(group(svg, "view-xc"), Catch::Contains("X-C (C against X)") && Catch::Contains("C [deg]") &&
                                        Catch::Contains("C -45.000 .. 0.000 deg"));
}

TEST_CASE("messprog check passes each shipped example program, and plot draws the bore inspection's 8 probe targets") {
  const std::string folder = std::string(IMESS_SOURCE_DIR) + "/examples/programs/";
  for (const char* name : {"bore-inspection.ngc", "mrm-manual.mrm", "pocket-helix.ngc", "shd-drawing.plt"}) {
    INFO(name);
    const auto r = run_program(messprog({"check", folder + name}));
    INFO(r.out << r.err);
    CHECK(r.status == 0);
    CHECK_THAT(r.out, Catch::StartsWith(folder + name + ": ok ("));
    CHECK(r.err.empty());
  }
  TempDir dir;
  const auto svg_path = dir.file("bore.svg");
  const auto r = run_program(messprog({"plot", folder + "bore-inspection.ngc", "-o", svg_path}));
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("8 probing moves"));
  const std::string svg = read_file(svg_path);
  for (const char* id : {"view-xy", "view-xz"}) {
    INFO(id);
    const auto view = group(svg, id);
    CHECK(count(view, "class=\"probe-target\"") == 8);
    CHECK(count(view, "<path class=\"probe\"") == 8);
  }
}

// ---- run ----

TEST_CASE("program events as messd words them: Block, ProgPause with its M0, ProgEnd with its text") {
  const auto b = parse_block("Block part.ngc 12 5/40");
  REQUIRE(b);
  CHECK((b->name == "part.ngc" && b->line == 12 && b->index == 5 && b->total == 40));
  const auto pause = parse_prog_pause("ProgPause part.ngc 17 M0");  // docs/protocol.md: <name> <line> M0
  REQUIRE(pause);
  CHECK((pause->name == "part.ngc" && pause->line == 17));
  CHECK(parse_prog_pause("ProgPause part.ngc 17"));
  CHECK_FALSE(parse_prog_pause("ProgPause part.ngc M0"));
  const auto end = parse_prog_end("ProgEnd part.ngc aborted 10 disconnected");
  REQUIRE(end);
  CHECK((end->outcome == ProgEndEvent::Outcome::Aborted && end->line == 10 && end->text == "disconnected"));
}

TEST_CASE("messprog run: Hello, Take, Upload with every line and '.', Run — progress — ProgEnd ok is exit 0") {
  ProgramPeerScript script;
  script.run = {"Ok Run {NAME}", "Block {NAME} 2 1/3", "Block {NAME} 3 2/3", "Block {NAME} 4 3/3", "ProgEnd {NAME} ok 4 end"};
  ProgramPeer peer(script);
  TempDir dir;
  const std::string program = "(square)\nG1 X10 F600\n\nG1 Y10\r\nG1 X0\n";
  const auto file = write(dir, "square.nc", program);
  const auto r = run_program(messprog({"run", file, peer.address()}));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  const auto got = peer.daemon().received();
  const std::vector<std::string> expected = {"Hello messprog", "Take", "Upload square.nc", "(square)", "G1 X10 F600",
                                             "", "G1 Y10", "G1 X0", ".", "Run"};
  CHECK(got == expected);
  CHECK(peer.uploaded_lines() == std::vector<std::string>{"(square)", "G1 X10 F600", "", "G1 Y10", "G1 X0"});
  CHECK_THAT(r.out, Catch::Contains("messd checked square.nc: gcode, 5 lines, 3 blocks, 2 segments, 20.000 mm, about 1.234 s"));
  // Not a terminal: plain progress lines, at most one a second (the three Blocks came at once).
  CHECK_THAT(r.out, Catch::Contains("square.nc: 0% line 2 block 1/3\n"));
  CHECK(count(r.out, "% line ") == 1);
  CHECK_THAT(r.out, Catch::Contains("messprog: square.nc ended ok at line 4"));
  CHECK(r.err.empty());
}

TEST_CASE("messprog run: a program of many kilobytes arrives line for line, blank lines included") {
  ProgramPeerScript script;
  script.run = {"Ok Run {NAME}", "ProgEnd {NAME} ok 1 end"};
  ProgramPeer peer(script);
  TempDir dir;
  std::string text;
  std::vector<std::string> lines;
  // 70 000 blank lines between two moves: more than one 64 KiB chunk, and a chunk that ends
  // with a blank line.
  lines.push_back("G0 X1");
  lines.insert(lines.end(), 70000, "");
  lines.push_back("G0 X2");
  for (const auto& l : lines) text += l + "\n";
  const auto file = write(dir, "big.nc", text);
  const auto r = run_program(messprog({"run", file, peer.address()}), std::chrono::seconds(20));
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(peer.uploaded_lines() == lines);
}

TEST_CASE("messprog run: ProgEnd failed is exit 1 with the line and its text — Run detached when asked") {
  ProgramPeerScript script;
  script.run = {"Ok Run {NAME}", "Block {NAME} 2 2/3", "ProgEnd {NAME} failed 2 Failed PartNotFound"};
  ProgramPeer peer(script);
  TempDir dir;
  const auto file = write(dir, "probe.ngc", "G0 Z5\nG38.2 Z-50 F100\nM2\n");
  const auto r = run_program(messprog({"run", file, peer.address(), "--detached"}));
  CHECK(r.status == 1);
  CHECK(peer.daemon().received().back() == "Run detached");
  CHECK_THAT(r.err, Catch::Contains("messprog: probe.ngc failed at line 2: Failed PartNotFound\n  2 | G38.2 Z-50 F100\n"));
}

TEST_CASE("messprog run: messd refusing the program is exit 1 with FILE:LINE:COL, and nothing is run") {
  ProgramPeerScript script;
  script.load = "Err 213 Upload {NAME}: line 2:1: unsupported code: found G81, accepted G0 G1 G2 G3";
  ProgramPeer peer(script);
  TempDir dir;
  const auto file = write(dir, "drill.tap", "G0 X1\nG81 X2\n");
  const auto r = run_program(messprog({"run", file, peer.address()}));
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("messprog: messd refused drill.tap (Err 213):\n" + file +
                                    ":2:1: unsupported code: found G81, accepted G0 G1 G2 G3\n"));
  CHECK(peer.daemon().received().back() == ".");  // no Run
}

TEST_CASE("messprog run: a refusal at the '.' that names no line (another program runs) is shown as messd says it") {
  ProgramPeerScript script;
  script.load = "Err 202 Upload: program other.ngc is running; Pause, Abort or wait for its ProgEnd";
  ProgramPeer peer(script);
  TempDir dir;
  const auto file = write(dir, "p.nc", "G0 X1\n");
  const auto r = run_program(messprog({"run", file, peer.address()}));
  CHECK(r.status == 1);
  CHECK(r.err == "messprog: messd refused p.nc: Err 202 Upload: program other.ngc is running; Pause, Abort or wait "
                 "for its ProgEnd\n");
  CHECK(peer.daemon().received().back() == ".");  // no Run
}

TEST_CASE("messprog run: the program's lines follow only an Ok Upload — a refused Upload sends none of them") {
  ProgramPeerScript script;
  // Control taken over between Take and Upload: had the lines gone out, each would be a command.
  script.upload = "Err 209 the machine is controlled by messjog at 127.0.0.1 (client 3)";
  ProgramPeer peer(script);
  TempDir dir;
  const auto file = write(dir, "p.nc", "G0 X1\nG0 X2\n");
  const auto r = run_program(messprog({"run", file, peer.address()}));
  CHECK(r.status == 1);
  CHECK(r.err == "messprog: messd refused Upload p.nc: Err 209 the machine is controlled by messjog at 127.0.0.1 "
                 "(client 3)\n");
  CHECK(peer.daemon().received() == std::vector<std::string>{"Hello messprog", "Take", "Upload p.nc"});
}

TEST_CASE("messprog run: a messd without programs, or control held by another client, is exit 1 before any upload") {
  TempDir dir;
  const auto file = write(dir, "p.nc", "G0 X1\n");
  {
    ProgramPeerScript script;
    script.hello = "Ok Hello IMESS 1 messd 0.1.0 Caps jog goto home probe hand stats journal queue sim";
    ProgramPeer peer(script);
    const auto r = run_program(messprog({"run", file, peer.address()}));
    CHECK(r.status == 1);
    CHECK_THAT(r.err, Catch::Contains("does not run programs") && Catch::Contains("'programs'"));
    CHECK(peer.daemon().received() == std::vector<std::string>{"Hello messprog"});
  }
  {
    ProgramPeerScript script;
    script.take = "Err 209 the machine is controlled by messjog at 127.0.0.1 (client 1)";
    ProgramPeer peer(script);
    const auto r = run_program(messprog({"run", file, peer.address()}));
    CHECK(r.status == 1);
    CHECK(r.err == "messprog: cannot take control of the machine: Err 209 the machine is controlled by messjog at "
                   "127.0.0.1 (client 1)\n");
    CHECK(peer.daemon().received() == std::vector<std::string>{"Hello messprog", "Take"});
  }
}

TEST_CASE("messprog run: Ctrl-C without a terminal sends Abort — ProgEnd aborted is exit 1") {
  ProgramPeerScript script;
  script.run = {"Ok Run {NAME}", "Block {NAME} 2 1/2"};  // and then nothing: it runs until stopped
  ProgramPeer peer(script);
  TempDir dir;
  const auto file = write(dir, "long.nc", "G1 X500 F60\nG1 X0\n");
  ChildProcess p(messprog({"run", file, peer.address()}));
  REQUIRE(peer.daemon().wait_for_line("Run"));
  REQUIRE(p.wait_for_output("line 2 block 1/2"));
  p.signal(SIGINT);
  const auto status = p.wait();
  REQUIRE(status);
  CHECK(*status == 1);
  CHECK(peer.daemon().received().back() == "Abort");
  CHECK_THAT(p.err(), Catch::Contains("messprog: long.nc aborted at line 2: Abort"));
}

TEST_CASE("messprog run: a lost connection while running is exit 1 saying so") {
  ProgramPeerScript script;
  script.run = {"Ok Run {NAME}", "Block {NAME} 1 1/2"};
  ProgramPeer peer(script);
  TempDir dir;
  const auto file = write(dir, "long.nc", "G1 X500 F60\nG1 X0\n");
  ChildProcess p(messprog({"run", file, peer.address()}));
  REQUIRE(p.wait_for_output("block 1/2"));
  peer.daemon().drop_clients();
  const auto status = p.wait();
  REQUIRE(status);
  CHECK(*status == 1);
  CHECK_THAT(p.err(), Catch::Contains("messprog: lost the connection to " + peer.address() + " (closed by messd) while long.nc ran") &&
                          Catch::Contains("--detached"));
}

TEST_CASE("messprog run: a file that cannot be sent is refused before connecting, naming the line") {
  imess::test::FakeDaemon daemon;
  TempDir dir;
  const auto dot = write(dir, "dot.nc", "G0 X1\n.\nG0 X2\n");
  auto r = run_program(messprog({"run", dot, daemon.address()}));
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: " + dot + ":2: a line holding only '.' ends an Upload"));
  const auto longer = write(dir, "long.nc", "G0 X1\n(" + std::string(250, 'x') + ")\n");
  r = run_program(messprog({"run", longer, daemon.address()}));
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: " + longer + ":2: line of 252 characters; messd accepts lines of at most 200"));
  r = run_program(messprog({"run", dir.file("none.nc"), daemon.address()}));
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: cannot read '" + dir.file("none.nc") + "'"));
  CHECK(daemon.accepted() == 0);
}

TEST_CASE("upload_name: the base name, blanks replaced, the language's extension added when --lang named another") {
  using imess::programs::Language;
  CHECK(upload_name("/a/b/part.nc", Language::Gcode) == "part.nc");
  CHECK(upload_name("my part.NGC", Language::Gcode) == "my_part.NGC");
  CHECK(upload_name("part.txt", Language::Gcode) == "part.txt.nc");
  CHECK(upload_name("pen.nc", Language::Hpgl) == "pen.nc.plt");
  CHECK(upload_name("arm", Language::Mrm) == "arm.mrm");
}

TEST_CASE("RunSession on a terminal: Ctrl-C pauses and asks — r resumes, a aborts, a second Ctrl-C aborts") {
  Upload upload{"p.nc", {"G0 X1", "M0", "G0 X2"}};
  RunSession s(upload, {"p.nc", "localhost:1066", false, true});
  CHECK(s.start().send == std::vector<std::string>{"Hello messprog"});
  CHECK(s.on_line("Ok Hello IMESS 1 messd 0.1.0 Caps queue programs").send == std::vector<std::string>{"Take"});
  CHECK(s.on_line("Ok Take").send == std::vector<std::string>{"Upload p.nc"});
  CHECK(s.on_line("Ok Upload p.nc send the lines, then a line '.'").send ==
        std::vector<std::string>{"G0 X1", "M0", "G0 X2", "."});
  CHECK(s.on_line("Ok Load p.nc Lang gcode").send == std::vector<std::string>{"Run"});
  CHECK(s.on_line("Ok Run p.nc").notes.size() == 1);
  CHECK(s.phase() == RunSession::Phase::Running);
  CHECK(s.on_line("Block p.nc 1 1/3").block->index == 1);
  CHECK_FALSE(s.on_line("Block other.nc 1 1/3").block);  // someone else's program

  auto out = s.interrupt();
  CHECK(out.send == std::vector<std::string>{"Pause"});
  CHECK(out.ask);
  out = s.answer("x");  // neither: asked again
  CHECK(out.send.empty());
  CHECK(out.ask);
  CHECK(s.answer("r\n").send == std::vector<std::string>{"Resume"});
  CHECK_FALSE(s.asking());

  out = s.on_line("ProgPause p.nc 2 M0");  // M0, as messd words it: the same question
  CHECK(out.ask);
  CHECK(out.notes == std::vector<std::string>{"messprog: M0 at line 2: the machine waits"});
  CHECK(s.answer(" r").send == std::vector<std::string>{"Resume"});

  CHECK(s.interrupt().send == std::vector<std::string>{"Pause"});
  CHECK(s.interrupt().send == std::vector<std::string>{"Abort"});  // Ctrl-C again while asked
  CHECK(s.on_line("Ok Abort").send.empty());
  out = s.on_line("ProgEnd p.nc aborted 3 Abort");
  REQUIRE(out.exit);
  CHECK(*out.exit == 1);
  CHECK(out.errors == std::vector<std::string>{"messprog: p.nc aborted at line 3: Abort", "  3 | G0 X2"});
}

TEST_CASE("RunSession: Ctrl-C before Run ends at once — without a terminal it aborts, twice leaves") {
  Upload upload{"p.nc", {"G0 X1"}};
  RunSession early(upload, {"p.nc", "h:1", false, false});
  early.start();
  auto out = early.interrupt();
  REQUIRE(out.exit);
  CHECK(out.send.empty());

  RunSession s(upload, {"p.nc", "h:1", false, false});
  s.start();
  s.on_line("Ok Hello IMESS 1 messd 0.1.0 Caps programs");
  s.on_line("Ok Take");
  s.on_line("Ok Upload p.nc send the lines, then a line '.'");
  s.on_line("Ok Load p.nc");
  CHECK(s.interrupt().send == std::vector<std::string>{"Abort"});
  out = s.interrupt();
  CHECK(out.send.empty());
  REQUIRE(out.exit);
  CHECK(*out.exit == 1);
}

TEST_CASE("messprog's Ctrl-C and SIGTERM handlers restart interrupted writes (a failed write silences std::cout)") {
  struct sigaction saved_int {}, saved_term {};
  sigaction(SIGINT, nullptr, &saved_int);
  sigaction(SIGTERM, nullptr, &saved_term);
  imess::messprog::install_interrupts();
  struct sigaction now {};
  sigaction(SIGINT, nullptr, &now);
  CHECK((now.sa_flags & SA_RESTART) != 0);
  sigaction(SIGTERM, nullptr, &now);
  CHECK((now.sa_flags & SA_RESTART) != 0);
  sigaction(SIGINT, &saved_int, nullptr);
  sigaction(SIGTERM, &saved_term, nullptr);
}

TEST_CASE("ProgressView: percent of blocks done, a bar on a terminal, plain lines at most once a second") {
  BlockEvent b{"p.nc", 120, 451, 1000};
  CHECK(ProgressView::percent(b) == 45);
  CHECK(ProgressView::bar(b, 45) == "p.nc [#############-----------------]  45%  line 120  block 451/1000");
  ProgressView tty(true);
  CHECK(tty.update(b) == "\r\x1b[K" + ProgressView::bar(b, 45));
  CHECK(tty.done(true) == "\r\x1b[K" + ProgressView::bar(b, 100) + "\n");
  ProgressView plain(false);
  const auto t0 = ProgressView::Clock::now();
  CHECK(plain.update(b, t0) == "p.nc: 45% line 120 block 451/1000\n");
  CHECK(plain.update(b, t0 + std::chrono::milliseconds(900)).empty());
  CHECK_FALSE(plain.update(b, t0 + std::chrono::milliseconds(1000)).empty());
  CHECK(plain.done(true).empty());
}

TEST_CASE("messprog check and plot --config FILE: messd's machine — its travel, start, programs section and check") {
  TempDir dir;
  const std::string config = std::string(IMESS_SOURCE_DIR) + "/config/sim-servo-card.json";
  // From where the simulation powers on (430 330 100), not from 0 0 0.
  const auto file = write(dir, "near.ngc", "G91 G0 X10\n");
  auto r = run_program(messprog({"check", file, "--config", config}));
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("path length 10.000 mm"));
  CHECK_THAT(r.out, Catch::Contains("starting at 430 330 100 (where the simulation powers on)"));
  CHECK_THAT(r.out, Catch::Contains("Z 0..600 150 mm/s 1000 mm/s²"));
  // The machine's travel: Z 0..600, so Z-5 is outside (the generic machine has -1000..1000).
  const auto low = write(dir, "low.ngc", "G0 Z-5\n");
  CHECK(run_program(messprog({"check", low})).status == 0);
  r = run_program(messprog({"check", low, "--config", config}));
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("low.ngc:1:"));
  // The programs section: on the SHD machine HPGL's origin is 430 330 and the pen moves Z
  // between 100 (up) and 90 (down); the generic machine draws from 0 0 with the pen at 5 / 0.
  const auto plt = write(dir, "line.plt", "IN;PU0,0;PD400,0;PU;\n");
  r = run_program(messprog({"check", plt, "--config", std::string(IMESS_SOURCE_DIR) + "/config/sim-parport-shd.json"}));
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("  X      430.000 ..      440.000 mm\n"));
  CHECK_THAT(r.out, Catch::Contains("  Z       90.000 ..      100.000 mm\n"));
  r = run_program(messprog({"check", plt}));
  CHECK_THAT(r.out, Catch::Contains("  Z        0.000 ..        5.000 mm\n"));
  // --from overrides the start; --axes and --travel do not go with it; a bad file is exit 2.
  r = run_program(messprog({"check", file, "--config", config, "--from", "0,0,0"}));
  CHECK_THAT(r.out, Catch::Contains("starting at 0 0 0\n"));
  r = run_program(messprog({"check", file, "--config", config, "--travel", "-5:5"}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("--travel with --config"));
  r = run_program(messprog({"check", file, "--config", write(dir, "bad.json", "{\"axes\": 3}")}));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::StartsWith("messprog: --config "));
  const auto svg = dir.file("near.svg");
  CHECK(run_program(messprog({"plot", file, "--config", config, "-o", svg})).status == 0);
  CHECK_THAT(group(read_file(svg), "view-xy"), Catch::Contains("box: X 430.000 .. 440.000 mm"));
}
