// messoffs, run as a program: BRIEF §3's six reference rows (rotated and corrected) from the
// shipped tables and from corrections typed on the command line, the 180° design-frame example,
// the written JSON pairs and G10 program read back, the confirmation, and bad input named.
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "confirm.hpp"
#include "gcode_program.hpp"
#include "imess/metrology/frame_store.hpp"
#include "offs_command.hpp"
#include "offs_options.hpp"
#include "table_csv.hpp"
#include "table_json.hpp"

using imess::test::client_binary;
using imess::test::file_exists;
using imess::test::read_file;
using imess::test::run_program;
using imess::test::TempDir;
using Eigen::Vector3d;

namespace {

constexpr double kTol = 1e-9;
const std::string kExamples = std::string(IMESS_SOURCE_DIR) + "/examples/offsets/";

// BRIEF §3, "Reference tables": inputs, stored corrections and the two result columns.
struct Row {
  int clamping;
  const char* name;
  Vector3d p;
  double a, b;
  Vector3d correction;  // in the offset's own axes
  Vector3d rotated, corrected;
};
const Vector3d kFirst(-327.957, 612.5, 222.0);
const Vector3d kSecond(287.5, -40.5, -60.0);
const std::vector<Row> kReference = {
    {1, "G510", kFirst, 0, 0, {0.2, 0, 0}, {-327.957, 612.5, 222.0}, {-327.757, 612.5, 222.0}},
    {1, "G511", kFirst, 0, 270, {0.2, 0, 0}, {222.0, 612.5, 327.957}, {222.0, 612.5, 327.757}},
    {1, "G512", kFirst, -90, 180, {0.2, 0, -0.2}, {327.957, 222.0, 612.5}, {327.757, 221.8, 612.5}},
    {1, "G513", kFirst, 0, 90, {0.2, 0, 0}, {-222.0, 612.5, -327.957}, {-222.0, 612.5, -327.757}},
    {2, "G510", kSecond, 0, 180, {0, 0, 0}, {-287.5, -40.5, 60.0}, {-287.5, -40.5, 60.0}},
    {2, "G512", kSecond, -90, 0, {0, 0, 0.2}, {287.5, 60.0, -40.5}, {287.5, 59.8, -40.5}},
};

std::string key(int clamping, const std::string& name) { return std::to_string(clamping) + "/" + name; }

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

Vector3d vec_at(const std::vector<std::string>& w, std::size_t i) {
  return {std::stod(w.at(i)), std::stod(w.at(i + 1)), std::stod(w.at(i + 2))};
}

struct Shown {
  Vector3d rotated, corrected;
};

// The machine table: "clamping name P A B | rx ry rz | cx cy cz", up to the first empty line.
std::map<std::string, Shown> machine_rows(const std::string& out) {
  std::map<std::string, Shown> rows;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line) && line.rfind("clamping", 0) != 0) {
  }
  while (std::getline(in, line) && !line.empty()) {
    auto w = words(line);
    REQUIRE(w.size() == 13);
    REQUIRE(w[5] == "|");
    REQUIRE(w[9] == "|");
    rows[key(std::stoi(w[0]), w[1])] = {vec_at(w, 6), vec_at(w, 10)};
  }
  return rows;
}

// The design table after "in design frame": "clamping name | x y z | dx dy dz".
std::map<std::string, Shown> design_rows(const std::string& out) {
  std::map<std::string, Shown> rows;
  auto at = out.find("\nin design frame");
  REQUIRE(at != std::string::npos);
  std::istringstream in(out.substr(at + 1));
  std::string line;
  std::getline(in, line);
  std::getline(in, line);  // header
  while (std::getline(in, line) && !line.empty()) {
    auto w = words(line);
    REQUIRE(w.size() == 10);
    rows[key(std::stoi(w[0]), w[1])] = {vec_at(w, 3), vec_at(w, 7)};  // {point, correction}
  }
  return rows;
}

// "G10 L2 P3 X327.757 Y221.8 Z612.5 (G512 A-90.0 B180.0)" -> P -> XYZ.
std::map<int, Vector3d> g10_lines(const std::string& program) {
  std::map<int, Vector3d> out;
  std::istringstream in(program);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("G10 ", 0) != 0) continue;
    auto w = words(line);
    REQUIRE(w.size() >= 6);
    CHECK(w[1] == "L2");
    REQUIRE(w[2][0] == 'P');
    REQUIRE(w[3][0] == 'X');
    REQUIRE(w[4][0] == 'Y');
    REQUIRE(w[5][0] == 'Z');
    for (int k = 3; k <= 5; ++k) CHECK(w[static_cast<std::size_t>(k)].find('.') != std::string::npos);
    out[std::stoi(w[2].substr(1))] = {std::stod(w[3].substr(1)), std::stod(w[4].substr(1)), std::stod(w[5].substr(1))};
  }
  return out;
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The reference inputs without their corrections, P numbers 1..4 by offset.
std::string base_table_csv() {
  std::string csv = "clamping,name,p,x,y,z,a,b\n";
  const std::map<std::string, int> p = {{"G510", 1}, {"G511", 2}, {"G512", 3}, {"G513", 4}};
  for (const auto& r : kReference) {
    std::ostringstream line;
    line.precision(17);
    line << r.clamping << "," << r.name << "," << p.at(r.name) << "," << r.p.x() << "," << r.p.y() << "," << r.p.z()
         << "," << r.a << "," << r.b << "\n";
    csv += line.str();
  }
  return csv;
}

// "x=0.2,z=-0.2" for a correction vector (axes that are 0 left out).
std::string correction_text(const Vector3d& c) {
  std::string out;
  const char* axes[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    if (c(k) == 0.0) continue;
    std::ostringstream v;
    v.precision(17);
    v << axes[k] << "=" << (c(k) > 0 ? "+" : "") << c(k);
    out += (out.empty() ? "" : ",") + v.str();
  }
  return out;
}

// A frame store holding `name`: design -> machine with rotation r and translation t.
void write_frames(const std::string& path, const std::string& name, const Eigen::Matrix3d& r, const Vector3d& t) {
  imess::metrology::FrameStore store;
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = r;
  m.topRightCorner<3, 1>() = t;
  store.set(name, m);
  imess::metrology::save_frame_store(path, store);
}

}  // namespace

TEST_CASE("messoffs shows the six reference rows rotated and corrected, from the shipped JSON and CSV") {
  for (const char* file : {"reference.json", "reference.csv"}) {
    INFO(file);
    auto r = run_program({client_binary("messoffs"), kExamples + file});
    INFO(r.err);
    REQUIRE(r.status == 0);
    auto rows = machine_rows(r.out);
    REQUIRE(rows.size() == kReference.size());
    for (const auto& ref : kReference) {
      INFO(key(ref.clamping, ref.name));
      const auto& shown = rows.at(key(ref.clamping, ref.name));
      CHECK((shown.rotated - ref.rotated).cwiseAbs().maxCoeff() < kTol);
      CHECK((shown.corrected - ref.corrected).cwiseAbs().maxCoeff() < kTol);
    }
  }
}

TEST_CASE("messoffs --correct reproduces the corrected column from the bases, writes pairs and G10 lines") {
  TempDir dir;
  write_text(dir.file("base.csv"), base_table_csv());
  // Clamping 1, then clamping 2 on the table the first run wrote (G510 and G512 are in both).
  std::string table = dir.file("base.csv");
  for (int clamping : {1, 2}) {
    INFO("clamping " << clamping);
    const std::string written = dir.file("c" + std::to_string(clamping) + ".json");
    const std::string program = dir.file("c" + std::to_string(clamping) + ".ngc");
    std::vector<std::string> argv{client_binary("messoffs"), table, "--clamping", std::to_string(clamping)};
    for (const auto& ref : kReference)
      if (ref.clamping == clamping && ref.correction != Vector3d::Zero())
        argv.insert(argv.end(), {"--correct", ref.name, correction_text(ref.correction)});
    argv.insert(argv.end(), {"--yes", "--write", written, "--gcode", program});
    auto r = run_program(argv);
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    // The before/after lines of each correction.
    for (const auto& ref : kReference) {
      if (ref.clamping != clamping || ref.correction == Vector3d::Zero()) continue;
      auto at = r.out.find("correction of " + std::string(ref.name) + " (clamping " + std::to_string(clamping));
      REQUIRE(at != std::string::npos);
      auto block = r.out.substr(at);
      auto line_after = [&](const std::string& label) {
        auto pos = block.find(label);
        REQUIRE(pos != std::string::npos);
        auto w = words(block.substr(pos + label.size(), block.find('\n', pos) - pos - label.size()));
        REQUIRE(w.size() == 3);
        return vec_at(w, 0);
      };
      CHECK((line_after("before (rotated, the G10 values):") - ref.rotated).cwiseAbs().maxCoeff() < kTol);
      CHECK((line_after("after  (rotated, the G10 values):") - ref.corrected).cwiseAbs().maxCoeff() < kTol);
    }
    // The G10 program holds this clamping's corrected offsets, by P number.
    auto g10 = g10_lines(read_file(program));
    const std::map<std::string, int> p = {{"G510", 1}, {"G511", 2}, {"G512", 3}, {"G513", 4}};
    std::size_t expected = 0;
    for (const auto& ref : kReference) {
      if (ref.clamping != clamping) continue;
      ++expected;
      INFO(ref.name);
      REQUIRE(g10.count(p.at(ref.name)) == 1);
      CHECK((g10.at(p.at(ref.name)) - ref.corrected).cwiseAbs().maxCoeff() < 1e-6);  // six decimals
    }
    CHECK(g10.size() == expected);
    CHECK_THAT(read_file(program), Catch::Contains("G21\n") && Catch::EndsWith("M2\n"));
    table = written;
  }
  // The final table: every base as it was, the corrections stored as pairs, all six rows.
  auto doc = nlohmann::json::parse(read_file(table));
  REQUIRE(doc["offsets"].size() == kReference.size());
  for (const auto& row : doc["offsets"]) {
    const auto& ref = *std::find_if(kReference.begin(), kReference.end(), [&](const Row& x) {
      return x.clamping == row["clamping"].get<int>() && row["name"] == x.name;
    });
    INFO(key(ref.clamping, ref.name));
    const char* axes[] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
      CHECK(row[axes[k]][0].get<double>() == ref.p(k));  // the base is never overwritten
      CHECK(row[axes[k]][1].get<double>() == Approx(ref.correction(k)).margin(1e-12));
    }
  }
  auto shown = run_program({client_binary("messoffs"), table});
  REQUIRE(shown.status == 0);
  auto rows = machine_rows(shown.out);
  for (const auto& ref : kReference) {
    INFO(key(ref.clamping, ref.name));
    CHECK((rows.at(key(ref.clamping, ref.name)).rotated - ref.rotated).cwiseAbs().maxCoeff() < kTol);
    CHECK((rows.at(key(ref.clamping, ref.name)).corrected - ref.corrected).cwiseAbs().maxCoeff() < kTol);
  }
}

TEST_CASE("messoffs: corrections accumulate next to the base, over runs and within one") {
  TempDir dir;
  write_text(dir.file("t.csv"), "name,p,x,y,z,a,b,dx\nG54,,10,20,30,0,0,0.05\n");
  auto r = run_program({client_binary("messoffs"), dir.file("t.csv"), "--correct", "G54", "x=0.1", "--correct", "G54",
                        "x=+0.1,y=-0.3", "--yes", "--write", dir.file("t.json")});
  INFO(r.err);
  REQUIRE(r.status == 0);
  auto row = nlohmann::json::parse(read_file(dir.file("t.json")))["offsets"][0];
  CHECK(row["p"] == 1);  // G54 implies P1
  CHECK(row["x"][0].get<double>() == 10.0);
  CHECK(row["x"][1].get<double>() == Approx(0.25).margin(1e-12));
  CHECK(row["y"][0].get<double>() == 20.0);
  CHECK(row["y"][1].get<double>() == Approx(-0.3).margin(1e-12));
  CHECK(row["z"][1].get<double>() == 0.0);
}

TEST_CASE("messoffs design frame: 180 degrees about z turns -0.200 in design x into +0.200 in machine x") {
  TempDir dir;
  write_text(dir.file("t.csv"), "name,p,x,y,z,a,b\nG510,1,-327.957,612.5,222.0,0,0\n");
  // The shipped frame (no translation) and the same turn with its origin elsewhere: a correction
  // is a direction, so the translation must not reach it.
  write_frames(dir.file("moved.json"), "turned", Vector3d(-1, -1, 1).asDiagonal(), Vector3d(100, 200, 30));
  for (const std::string& frames : {kExamples + "design-frames.json", dir.file("moved.json")}) {
    INFO(frames);
    const std::string out_json = dir.file("out.json"), out_ngc = dir.file("out.ngc");
    auto r = run_program({client_binary("messoffs"), dir.file("t.csv"), "--frame", "turned", "--frames", frames,
                          "--correct", "G510", "x=-0.200", "--yes", "--force", "--write", out_json, "--gcode", out_ngc});
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    CHECK_THAT(r.out, Catch::Contains("in design frame 'turned'"));
    auto row = nlohmann::json::parse(read_file(out_json))["offsets"][0];
    CHECK(row["x"][1].get<double>() == Approx(0.200).margin(1e-12));
    CHECK(row["y"][1].get<double>() == Approx(0.0).margin(1e-12));
    CHECK(row["z"][1].get<double>() == Approx(0.0).margin(1e-12));
    CHECK(row["x"][0].get<double>() == -327.957);
    CHECK((g10_lines(read_file(out_ngc)).at(1) - Vector3d(-327.757, 612.5, 222.0)).cwiseAbs().maxCoeff() < 1e-6);
    // The offset shown in the design frame is a point (the full map), its correction a direction.
    const Vector3d t = frames == dir.file("moved.json") ? Vector3d(100, 200, 30) : Vector3d::Zero();
    auto shown = run_program({client_binary("messoffs"), out_json, "--frame", "turned", "--frames", frames});
    REQUIRE(shown.status == 0);
    auto design = design_rows(shown.out).at(key(1, "G510"));
    const Vector3d machine(-327.757, 612.5, 222.0);
    const Vector3d expect_point = Vector3d(-1, -1, 1).asDiagonal() * (machine - t);
    CHECK((design.rotated - expect_point).cwiseAbs().maxCoeff() < kTol);
    CHECK((design.corrected - Vector3d(-0.2, 0, 0)).cwiseAbs().maxCoeff() < kTol);
  }
}

TEST_CASE("messoffs design frame: a correction typed in the rotated axes is turned back into the offset's axes") {
  // With a frame whose axes are the machine's, a correction is typed in the axes the offset is
  // shown in (after Rx(-A)·Ry(-B)). G512's row moves by (-0.2, -0.2, 0) there, which is the
  // stored x +0.2, z -0.2 of the reference table.
  TempDir dir;
  write_text(dir.file("t.csv"), "name,p,x,y,z,a,b\nG512,3,-327.957,612.5,222.0,-90,180\n");
  write_frames(dir.file("f.json"), "machine", Eigen::Matrix3d::Identity(), Vector3d(5, -7, 11));
  auto r = run_program({client_binary("messoffs"), dir.file("t.csv"), "--frame", "machine", "--frames",
                        dir.file("f.json"), "--correct", "G512", "x=-0.2,y=-0.2", "--yes", "--write", dir.file("o.json")});
  INFO(r.out << r.err);
  REQUIRE(r.status == 0);
  auto row = nlohmann::json::parse(read_file(dir.file("o.json")))["offsets"][0];
  CHECK(row["x"][1].get<double>() == Approx(0.2).margin(1e-12));
  CHECK(row["y"][1].get<double>() == Approx(0.0).margin(1e-12));
  CHECK(row["z"][1].get<double>() == Approx(-0.2).margin(1e-12));
  auto shown = run_program({client_binary("messoffs"), dir.file("o.json")});
  CHECK((machine_rows(shown.out).at(key(1, "G512")).corrected - Vector3d(327.757, 221.8, 612.5)).cwiseAbs().maxCoeff() <
        kTol);
}

TEST_CASE("messoffs: corrections are confirmed on a terminal, refused without one, nothing written unconfirmed") {
  TempDir dir;
  const std::string table = kExamples + "reference.json";
  const std::string out = dir.file("out.json");
  auto r = run_program({client_binary("messoffs"), table, "--clamping", "1", "--correct", "G510", "x=0.1", "--write", out});
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("no terminal to confirm them on") && Catch::Contains("--yes"));
  CHECK_THAT(r.out, Catch::Contains("after  (rotated, the G10 values):"));  // shown all the same
  CHECK_FALSE(file_exists(out));

  // The run itself, with the terminal's answers given as a stream.
  const char* argv[] = {"messoffs", table.c_str(), "--clamping", "1", "--correct", "G510", "x=0.1", "--write", out.c_str()};
  const auto options = imess::messoffs::parse_offs_options(9, argv);
  for (const char* answer : {"n\n", "\n", "", "yes please\n"}) {
    INFO("answer '" << answer << "'");
    std::ostringstream o, e;
    std::istringstream in(answer);
    CHECK(imess::messoffs::run_offs(options, o, e, in, true) == 1);
    CHECK_THAT(e.str(), Catch::Contains("[y/N]") && Catch::Contains("not confirmed; nothing written"));
    CHECK_FALSE(file_exists(out));
  }
  std::ostringstream o, e;
  std::istringstream yes(" Y \n");
  CHECK(imess::messoffs::run_offs(options, o, e, yes, true) == 0);
  REQUIRE(file_exists(out));
  CHECK(nlohmann::json::parse(read_file(out))["offsets"][0]["x"][1].get<double>() == Approx(0.3).margin(1e-12));
}

TEST_CASE("messoffs: bad command lines and tables are named with what is accepted") {
  TempDir dir;
  const std::string ref = kExamples + "reference.json";
  write_text(dir.file("exists.json"), "{}");
  write_text(dir.file("nop.csv"), "name,x,y,z,a,b\nG510,1,2,3,0,0\n");
  write_text(dir.file("bad.csv"), "# offsets\nname,x,y,z,a,b\nG510,1,2,3,0,0\nG511,1,two,3,0,0\n");
  struct Case {
    std::vector<std::string> args;
    int status;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{}, 2, "missing TABLE"},
      {{ref, "--bogus"}, 2, "unknown option '--bogus'; accepted: --clamping N"},
      {{ref, "--correct", "G510"}, 2, "--correct needs OFFSET and AXIS=MM"},
      {{ref, "--correct", "G510", "q=1", "--yes", "--write", dir.file("o.json")}, 2, "--correct 'q=1': not AXIS=MM"},
      {{ref, "--correct", "G510", "x=1,x=2", "--write", dir.file("o.json")}, 2, "axis x given twice"},
      {{ref, "--correct", "G510", "x=0.1mm", "--write", dir.file("o.json")}, 2, "expected a correction in mm"},
      {{ref, "--correct", "G510", "x=0.1"}, 2, "needs somewhere to write the result"},
      {{ref, "--write", dir.file("o.csv")}, 2, "the table is written as JSON"},
      {{ref, "--frame", "turned"}, 2, "--frame NAME and --frames FILE go together"},
      {{ref, "--clamping", "0"}, 2, "--clamping '0': expected a whole number 1..999"},
      {{ref, "--clamping", "7"}, 2, "--clamping 7: no offsets of that clamping"},
      {{ref, "--gcode", dir.file("o.ngc")}, 2, "the table has clampings 1, 2: choose one with --clamping N"},
      {{ref, "--correct", "G510", "x=0.1", "--yes", "--write", dir.file("o.json")}, 1,
       "offset 'G510' is in clampings 1, 2; choose one with --clamping N"},
      {{ref, "--clamping", "2", "--correct", "G511", "x=0.1", "--yes", "--write", dir.file("o.json")}, 1,
       "no offset 'G511' in clamping 2; the table has: G510, G512"},
      {{ref, "--write", dir.file("exists.json")}, 1, "exists; add --force to replace it"},
      {{dir.file("nop.csv"), "--gcode", dir.file("o.ngc")}, 1, "offset 'G510' (clamping 1) has no P number"},
      {{dir.file("bad.csv")}, 1, "bad.csv:4: column 'y': expected the base y in mm, a finite number, got 'two'"},
      {{dir.file("t.txt")}, 1, "unknown table format; accepted: .json, .csv"},
      {{dir.file("missing.json")}, 1, "missing.json': cannot open for reading"},
      {{ref, "--frame", "nope", "--frames", kExamples + "design-frames.json"}, 1,
       "no frame named 'nope'; the store holds: turned"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> argv{client_binary("messoffs")};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    INFO(c.expected);
    auto r = run_program(argv);
    CHECK(r.status == c.status);
    CHECK_THAT(r.err, Catch::StartsWith("messoffs: ") && Catch::Contains(c.expected));
    if (c.status == 2) CHECK_THAT(r.err, Catch::Contains("(try messoffs --help)"));
  }
  CHECK_FALSE(file_exists(dir.file("o.json")));
  CHECK_FALSE(file_exists(dir.file("o.ngc")));
  CHECK(read_file(dir.file("exists.json")) == "{}");
}

TEST_CASE("offset table parsers: each mistake named by file and line or key") {
  using imess::messoffs::parse_table_csv;
  using imess::messoffs::parse_table_json;
  using imess::messoffs::TableError;
  struct Case {
    bool json;
    const char* text;
    const char* expected;
  };
  const std::vector<Case> cases = {
      {false, "", "t: no header line"},
      {false, "name,x,y,z,a\n", "t:1: header: column 'b' missing (required: name, x, y, z, a, b"},
      {false, "name,x,y,z,a,b,c\n", "t:1: header: unknown column 'c'; accepted: name, clamping, p"},
      {false, "name,x,x,y,z,a,b\n", "t:1: header: column 'x' appears twice"},
      {false, "name,x,y,z,a,b\n", "t: no offsets"},
      {false, "name,x,y,z,a,b\nG510,1,2,3,0\n", "t:2: 5 fields, the header has 6"},
      {false, "name,x,y,z,a,b\nG 510,1,2,3,0,0\n", "t:2: column 'name': expected an offset name of letters"},
      {false, "name,x,y,z,a,b\n,1,2,3,0,0\n", "t:2: column 'name': empty"},
      {false, "name,x,y,z,a,b\nG510,1,2,,0,0\n", "t:2: column 'z': empty (expected the base z in mm)"},
      {false, "name,x,y,z,a,b\nG510,1,2,3,0,nan\n", "t:2: column 'b': expected the B angle in degrees"},
      {false, "name,x,y,z,a,b,p\nG510,1,2,3,0,0,10\n", "t:2: column 'p': expected the G10 L2 P number (P1..P9 = G54..G59.3), a whole number 1..9, got 10"},
      {false, "name,x,y,z,a,b,clamping\nG510,1,2,3,0,0,1.5\n", "t:2: column 'clamping': expected the clamping, a whole number 1..999, got 1.5"},
      {false, "name,x,y,z,a,b,dx\nG510,1,2,3,0,0,+-1\n", "t:2: column 'dx': expected the correction in mm"},
      {false, "name,x,y,z,a,b\nG510,1,2,3,0,0\nG510,1,2,3,0,0\n", "t: offset 'G510' appears twice in clamping 1"},
      {false, "name,p,x,y,z,a,b\nG510,1,1,2,3,0,0\nG54,,1,2,3,0,0\n", "t: offsets 'G510' and 'G54' both have P1 in clamping 1"},
      {true, "[1]", "t: expected a JSON object with an \"offsets\" array"},
      {true, "{\"offsets\": []", "t: not valid JSON"},
      {true, "{\"offset\": []}", "t: offset: unknown key; accepted: units, offsets"},
      {true, "{\"units\": \"inch\", \"offsets\": []}", "t: units: only \"mm\" is accepted"},
      {true, "{\"offsets\": {}}", "t: offsets: missing or not an array"},
      {true, "{\"offsets\": [1]}", "t: offsets[0]: expected an object with name"},
      {true, "{\"offsets\": [{\"name\": \"G54\", \"x\": 1, \"y\": 2, \"z\": 3, \"a\": 0}]}", "t: offsets[0].b: missing"},
      {true, "{\"offsets\": [{\"name\": \"G54\", \"x\": 1, \"y\": 2, \"z\": 3, \"a\": 0, \"b\": 0, \"dx\": 1}]}",
       "t: offsets[0].dx: unknown key; accepted: name, clamping, p, a, b, x, y, z"},
      {true, "{\"offsets\": [{\"name\": 54, \"x\": 1, \"y\": 2, \"z\": 3, \"a\": 0, \"b\": 0}]}",
       "t: offsets[0].name: expected a string such as \"G510\", got 54"},
      {true, "{\"offsets\": [{\"name\": \"G54\", \"x\": [1], \"y\": 2, \"z\": 3, \"a\": 0, \"b\": 0}]}",
       "t: offsets[0].x: expected [base, correction] (mm), got [1]"},
      {true, "{\"offsets\": [{\"name\": \"G54\", \"x\": [1, \"0.2\"], \"y\": 2, \"z\": 3, \"a\": 0, \"b\": 0}]}",
       "t: offsets[0].x[1]: expected the correction in mm, got \"0.2\""},
      {true, "{\"offsets\": [{\"name\": \"G54\", \"x\": 1, \"y\": 2, \"z\": 3, \"a\": 0, \"b\": 0, \"p\": 0}]}",
       "t: offsets[0].p: expected the G10 L2 P number"},
      // issue 26, 7: a number beyond a double escaped as nlohmann's out_of_range (std::terminate)
      {true, "{\"offsets\":[{\"name\":\"G510\",\"x\":[1,1e309],\"y\":2,\"z\":3,\"a\":0,\"b\":0}]}",
       "t: key 'offsets[0].x[1]' holds a number too large for a double ('1e309'); numbers from"},
  };
  for (const auto& c : cases) {
    INFO(c.text);
    CHECK_THROWS_AS(c.json ? parse_table_json(c.text, "t") : parse_table_csv(c.text, "t"), TableError);
    CHECK_THROWS_WITH(c.json ? parse_table_json(c.text, "t") : parse_table_csv(c.text, "t"), Catch::StartsWith(c.expected));
  }
  // Accepted forms: CSV columns in any order, comments, CRLF, "+" signs; a JSON axis as a bare base.
  auto csv = parse_table_csv("# zero offsets\r\n\r\nb, a, z, y, x, name, dz\r\n90, -45, +3, 2, 1, G55, -0.5\r\n", "t");
  REQUIRE(csv.rows.size() == 1);
  CHECK(csv.rows[0].p == 2);
  CHECK(csv.rows[0].clamping == 1);
  CHECK(csv.rows[0].offset.a_deg == -45);
  CHECK(csv.rows[0].offset.b_deg == 90);
  CHECK(csv.rows[0].offset.base() == Vector3d(1, 2, 3));
  CHECK(csv.rows[0].offset.correction() == Vector3d(0, 0, -0.5));
  auto json = parse_table_json(R"({"offsets": [{"name": "G510", "x": 1, "y": [2, 0.1], "z": 3, "a": 0, "b": 0}]})", "t");
  CHECK_FALSE(json.rows[0].p.has_value());
  CHECK(json.rows[0].offset.correction() == Vector3d(0, 0.1, 0));
  // The writer's output reads back to the same table.
  auto back = parse_table_json(imess::messoffs::table_to_json(csv), "t");
  CHECK(back.rows[0].offset.base() == csv.rows[0].offset.base());
  CHECK(back.rows[0].offset.correction() == csv.rows[0].offset.correction());
  CHECK(back.rows[0].p == 2);
}

TEST_CASE("messoffs G-code numbers keep their decimal point and never read -0") {
  using imess::messoffs::gcode_number;
  CHECK(gcode_number(222.0) == "222.0");
  CHECK(gcode_number(-327.757) == "-327.757");
  CHECK(gcode_number(-7.3e-17) == "0.0");
  CHECK(gcode_number(0.1234567) == "0.123457");
  CHECK(gcode_number(-0.5) == "-0.5");
}

TEST_CASE("messoffs confirmation: only y or yes") {
  for (auto [answer, expected] : std::vector<std::pair<const char*, bool>>{
           {"y\n", true}, {"YES\n", true}, {"  yes  \n", true}, {"n\n", false}, {"\n", false}, {"", false}, {"yep\n", false}}) {
    INFO("'" << answer << "'");
    std::istringstream in(answer);
    std::ostringstream prompt;
    CHECK(imess::messoffs::confirmed(in, prompt, "apply?") == expected);
    CHECK(prompt.str() == "apply? [y/N] ");
  }
}
