// Property tests of messd's program runner (daemon/net/src/programs.cpp), on every shipped
// configuration with a "programs" section: for fixed seeds, a random small program valid for
// that machine is uploaded and a random sequence of actions from two clients is replayed
// against messd's own parts in virtual time (the golden harness, golden_harness.hpp) — Run,
// Run detached, Pause, Resume, Abort, StopMv, moves, jogs, Home, SetOut, Take, Release,
// disconnects and reconnects, programs that do not fit, waits. A third client only listens.
// Then the rules of the runner are checked on what the clients received:
//
//  1. every `Ok Run` is followed by exactly one `ProgEnd` for it before the next `Ok Run`,
//     and there is no `ProgEnd` without a run;
//  2. between `Ok Run` and its `ProgEnd` every command that moves the machine (and Load,
//     Run, an Upload's '.') is refused with `Err 202`, or `Err 209` from a client without
//     control — never `Ok`;
//  3. a stop while a program runs (StopMv, Abort from anyone; Release or a disconnect of the
//     controller; Take force) ends it at once, `ProgEnd … aborted <line> <who>`, and the
//     machine stands (`State idle`/`free`) within 3 s of virtual time; no run is aborted
//     without such a stop, and none fails; after any stop (a program's or not) nothing
//     moves until a command that moves is accepted after it;
//  4. a disconnect of the controller aborts a run started without `detached`; a detached run
//     goes on;
//  5. a program that does not fit never loads (`Err 213`, or 202/209 when refused before
//     the check), never changes the loaded program (every `Program` names the last program
//     loaded) and moves nothing (Status before and after);
//  6. every `Status` position lies within each axis' configured travel (the reference search
//     runs past a travel's end to its switch: while it runs, and after one stopped there
//     until the machine is referenced, within 5 mm);
//  7. `ProgEnd … ok` only when the program ran to its end: its Block lines never go back and
//     stay within the program, the ProgEnd names its last lines, and the machine stands at
//     the program's end pose within 0.01.
//
// Each kind of event the rules speak about is counted, and every configuration must have
// shown each at least once over its seeds: a rule never exercised proves nothing.
// IMESS_PROPERTY_SEEDS="1 2 99" replaces the fixed seeds (to explore more); a failing seed
// leaves its transcript, "# step N" before each step as the messages count them, in the
// temp directory (the path is in the failure message).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "shipped_config.hpp"
#include "config_rig.hpp"
#include "golden_harness.hpp"
#include "property_support.hpp"

using namespace imess;
using namespace imess::golden;

namespace {

// ---------------------------------------------------------------- the machine

struct MachineInfo {
  std::string config;  // "config/sim-servo-card.json"
  std::string letters;  // the machine's axes in order: "XYZ", "XYCUV"
  std::vector<double> travel_min, travel_max, start;
  std::vector<std::string> outputs;
  long period_us = 1000;
  bool hpgl = false;  // a plotter: programs.hpgl configured (pen on Z)
  double origin_x = 0, origin_y = 0, pen_up_z = 5;
  bool xyz() const { return letters == "XYZ"; }
};

MachineInfo machine_info(const std::string& config) {
  MachineInfo m;
  m.config = config;
  test::ConfigRig rig(std::string(IMESS_SOURCE_DIR) + "/" + config);
  const auto& cfg = rig.config();
  const auto& layout = cfg.core.layout;
  for (int a = 0; a < layout.count; ++a) {
    m.letters += layout.letters[a];
    m.travel_min.push_back(cfg.core.axes[a].travel_min);
    m.travel_max.push_back(cfg.core.axes[a].travel_max);
  }
  for (int i = 0; i < cfg.core.output_count; ++i) m.outputs.emplace_back(cfg.core.outputs[i].name_view());
  m.period_us = static_cast<long>(std::lround(cfg.period_us));
  const auto& pc = cfg.server.programs;
  m.hpgl = read_text(std::string(IMESS_SOURCE_DIR) + "/" + config).find("\"hpgl\"") != std::string::npos && pc.pen == "z";
  m.origin_x = pc.origin_x;
  m.origin_y = pc.origin_y;
  m.pen_up_z = pc.pen_up_z;
  // Where the simulated machine stands at power-on: its first Status.
  const auto out = replay(parse_transcript("@ " + config + "\n> Status\n", config), config);
  for (const auto& e : out)
    if (e.kind == EntryKind::Receive)
      if (auto s = parse_status(e.text)) m.start = s->pos;
  REQUIRE(m.start.size() == m.letters.size());
  return m;
}

// Every shipped configuration that runs programs.
std::vector<std::string> program_configs() {
  std::vector<std::string> out;
  for (const auto& f : std::filesystem::directory_iterator(std::string(IMESS_SOURCE_DIR) + "/config")) {
    if (f.path().extension() != ".json" || !imess::test::simulated_config(f.path())) continue;
    if (read_text(f.path().string()).find("\"programs\"") == std::string::npos) continue;
    out.push_back("config/" + f.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// ---------------------------------------------------------------- programs

struct Program {
  std::string name;
  std::vector<std::string> lines;
  bool relative = false;        // MRM: the end is the start plus `end`
  std::vector<double> end;      // per axis: the end pose (or the change); NaN: as at the start
  int last_motion_line = 0;     // 1-based
  bool has_m0 = false;
};

double nan() { return std::numeric_limits<double>::quiet_NaN(); }

// G-code on an XYZ machine: G0 to a point above the part near the start, then G1, G2/G3 (arcs
// and helices), G4, M0, within about 30 mm; never below the start's Z - 5 (the simulated part
// lies 20 mm below the start: the ball stays clear of it).
Program gcode_xyz(const MachineInfo& m, Random& r, const std::string& name) {
  Program p{name, {}, false, {nan(), nan(), nan()}};
  const double x0 = m.start[0], y0 = m.start[1], z0 = m.start[2];
  auto point = [&] {
    return std::array<double, 3>{r.coord(x0 - 30, x0 + 30), r.coord(y0 - 30, y0 + 30), r.coord(z0 - 5, z0 + 25)};
  };
  auto at = point();
  auto add = [&](const std::string& line, bool motion) {
    p.lines.push_back(line);
    if (motion) p.last_motion_line = static_cast<int>(p.lines.size());
  };
  add("G21 G90 G17", false);
  add("G0 X" + num(at[0]) + " Y" + num(at[1]) + " Z" + num(at[2]), true);
  const int n = r.pick(2, 5);
  for (int i = 0; i < n; ++i) {
    const int kind = r.pick(0, 99);
    const std::string feed = " F" + std::to_string(r.pick(12, 30) * 100);
    if (kind < 45) {
      at = point();
      add("G1 X" + num(at[0]) + " Y" + num(at[1]) + " Z" + num(at[2]) + feed, true);
    } else if (kind < 75) {  // an arc (a helix when Z changes) from where it is
      const double radius = r.real(3, 12), a0 = r.real(0, 2 * M_PI);
      const double i_off = std::round(-radius * std::cos(a0) * 1000) / 1000, j_off = std::round(-radius * std::sin(a0) * 1000) / 1000;
      const double cx = at[0] + i_off, cy = at[1] + j_off, rr = std::hypot(i_off, j_off);
      const double a1 = a0 + (r.chance(0.5) ? 1 : -1) * r.real(0.5, 5.5);
      at[0] = std::round((cx + rr * std::cos(a1)) * 1000) / 1000;
      at[1] = std::round((cy + rr * std::sin(a1)) * 1000) / 1000;
      std::string z;
      if (r.chance(0.3)) {
        at[2] = r.coord(z0 - 5, z0 + 25);
        z = " Z" + num(at[2]);
      }
      add(std::string(r.chance(0.5) ? "G2" : "G3") + " X" + num(at[0]) + " Y" + num(at[1]) + z + " I" + num(i_off) +
              " J" + num(j_off) + feed,
          true);
    } else if (kind < 87) {
      add("G4 P" + num(r.real(0.1, 0.6), 1), false);
    } else if (!p.has_m0) {
      add("M0", false);
      p.has_m0 = true;
    }
  }
  if (r.chance(0.5)) {
    at = point();
    add("G0 X" + num(at[0]) + " Y" + num(at[1]) + " Z" + num(at[2]), true);
  }
  if (r.chance(0.7)) add("M2", false);
  p.end = {at[0], at[1], at[2]};
  return p;
}

// G-code on a machine of other axes (the arm: X Y C U V): G0/G1 of every axis, G4, M0.
Program gcode_axes(const MachineInfo& m, Random& r, const std::string& name) {
  Program p{name, {}, false, std::vector<double>(m.letters.size(), nan())};
  std::vector<double> at(m.letters.size());
  auto pose = [&] {
    std::string s;
    for (std::size_t a = 0; a < m.letters.size(); ++a) {
      const double span = a < 2 ? 40 : 30;
      at[a] = r.coord(m.start[a] - span, m.start[a] + span);
      s += std::string(" ") + m.letters[a] + num(at[a]);
    }
    return s;
  };
  auto add = [&](const std::string& line, bool motion) {
    p.lines.push_back(line);
    if (motion) p.last_motion_line = static_cast<int>(p.lines.size());
  };
  add("G21 G90", false);
  add("G0" + pose(), true);
  const int n = r.pick(2, 4);
  for (int i = 0; i < n; ++i) {
    const int kind = r.pick(0, 99);
    if (kind < 65) {
      add("G1" + pose() + " F" + std::to_string(r.pick(12, 30) * 100), true);
    } else if (kind < 80) {
      add("G4 P" + num(r.real(0.1, 0.6), 1), false);
    } else if (!p.has_m0) {
      add("M0", false);
      p.has_m0 = true;
    }
  }
  if (r.chance(0.7)) add("M2", false);
  p.end = at;
  return p;
}

// MRM on the arm: one incremental word a line (0.1 mm / 0.1 degree), the gripper, M02.
Program mrm(const MachineInfo& m, Random& r, const std::string& name) {
  Program p{name, {}, true, std::vector<double>(m.letters.size(), 0.0)};
  int n = 0;
  auto add = [&](const std::string& word, bool motion) {
    p.lines.push_back("N" + std::to_string(++n) + " " + word);
    if (motion) p.last_motion_line = n;
  };
  add("F" + std::to_string(r.pick(10, 30) * 100), false);
  add("S" + std::to_string(r.pick(6, 18) * 100), false);
  // A B C move the arm's rotary axes in order (docs/programs.md, MRM): C U V here.
  std::vector<int> rotary;
  for (std::size_t a = 0; a < m.letters.size(); ++a)
    if (m.letters[a] != 'X' && m.letters[a] != 'Y' && m.letters[a] != 'Z') rotary.push_back(static_cast<int>(a));
  const int moves = r.pick(3, 6);
  for (int i = 0; i < moves; ++i) {
    const int kind = r.pick(0, 99);
    const int sign = r.chance(0.5) ? 1 : -1;
    if (kind < 40) {
      const int axis = r.pick(0, 1), v = sign * r.pick(50, 400);
      add(std::string(1, "XY"[axis]) + std::to_string(v), true);
      p.end[axis] += v / 10.0;
    } else if (kind < 85 && !rotary.empty()) {
      const int k = r.pick(0, static_cast<int>(std::min<std::size_t>(rotary.size(), 3)) - 1), v = sign * r.pick(50, 300);
      add(std::string(1, "ABC"[k]) + std::to_string(v), true);
      p.end[rotary[k]] += v / 10.0;
    } else {
      add(r.chance(0.5) ? "M03" : "M04", false);
    }
  }
  add("M02", false);
  return p;
}

// HPGL on the plotter: pen-up travel and pen-down strokes within 30 mm of its origin.
Program hpgl(const MachineInfo& m, Random& r, const std::string& name) {
  Program p{name, {}, false, {nan(), nan(), m.pen_up_z}};
  auto pt = [&] { return std::array<int, 2>{r.pick(-1200, 1200), r.pick(-1200, 1200)}; };
  auto xy = [](std::array<int, 2> q) { return std::to_string(q[0]) + "," + std::to_string(q[1]); };
  p.lines = {"IN;", "SP1;", "VS" + std::to_string(r.pick(1, 4)) + ";"};
  auto at = pt();
  p.lines.push_back("PU" + xy(at) + ";");
  const int n = r.pick(1, 3);
  for (int i = 0; i < n; ++i) {
    at = pt();
    std::string line = (r.chance(0.7) ? "PD" : "PU") + xy(at);
    if (r.chance(0.4)) {
      at = pt();
      line += "," + xy(at);
    }
    p.lines.push_back(line + ";");
  }
  at = pt();
  p.lines.push_back("PU" + xy(at) + ";");
  p.last_motion_line = static_cast<int>(p.lines.size());
  p.lines.push_back("SP0;");
  p.end[0] = m.origin_x + at[0] / 40.0;  // 40 plotter units a mm
  p.end[1] = m.origin_y + at[1] / 40.0;
  return p;
}

Program random_program(const MachineInfo& m, Random& r, int number) {
  const std::string base = "p" + std::to_string(number);
  if (m.hpgl && r.chance(0.5)) return hpgl(m, r, base + ".plt");
  if (m.xyz()) return gcode_xyz(m, r, base + ".ngc");
  if (r.chance(0.6)) return mrm(m, r, base + ".mrm");
  return gcode_axes(m, r, base + ".ngc");
}

// Programs that must not load on this machine: a Load from the examples folder, or an Upload.
struct BadProgram {
  std::string load;  // a Load of this example; else an Upload of:
  std::string name;
  std::vector<std::string> lines;
};

std::vector<BadProgram> bad_programs(const MachineInfo& m) {
  std::vector<BadProgram> bad = {
      {"", "bad1.ngc", {"G0 X" + num(m.start[0]) + " Y" + num(m.start[1]), "G1 X" + num(m.start[0] + 10) + " F600 #1"}},
      {"", "bad2.ngc", {"G0 X" + num(m.travel_max[0] + 100)}},  // out of travel
      {"", "bad3.plt", {"IN;", "CI100;"}},                       // HPGL without circles
      {"", "bad4.mrm", {"N1 X100"}},                             // no feed rate
  };
  if (m.xyz()) {
    bad.push_back({"", "bad5.ngc", {"G0 X" + num(m.start[0]) + " Y" + num(m.start[1]) + " Z" + num(m.start[2] + 20),
                                    "G2 X" + num(m.start[0]) + " Y" + num(m.start[1]) + " I0 J-" + num(m.travel_max[1]) + " F600"}});
    bad.push_back({"", "bad6.mrm", {"N1 S600", "N2 B900"}});  // no rotary axis
    bad.push_back({"mrm-manual.mrm", "", {}});
  } else {
    bad.push_back({"", "bad5.ngc", {"G0 Z5"}});  // the arm has no Z
    bad.push_back({"", "bad6.plt", {"IN;", "PU0,0;"}});  // a Z pen on a machine without Z
    bad.push_back({"bore-inspection.ngc", "", {}});
    bad.push_back({"shd-drawing.plt", "", {}});
  }
  return bad;
}

// ---------------------------------------------------------------- the script

struct BadLoadProbe {
  int before = 0, load = 0, after = 0;  // steps: Status, the Load/Upload, Status
};

struct Script {
  std::vector<Entry> entries;
  std::map<std::string, Program> programs;
  std::vector<BadLoadProbe> probes;
};

class Generator {
 public:
  Generator(const MachineInfo& m, std::uint64_t seed) : m_(m), r_(seed), bad_(bad_programs(m)) {}

  Script make(int actions) {
    s_.entries.push_back({EntryKind::Config, 1, m_.config});
    step_ = 0;
    connect(3);  // the observer: hears every broadcast, sends nothing
    send(1, "Hello p1");
    connect(2);
    send(2, "Hello p2");
    send(1, "Status");
    upload(1);
    for (int i = 0; i < actions; ++i) action();
    // The end: a stop, time to brake, what is left.
    if (!connected_[2]) reconnect(2);
    send(2, "Abort");
    wait(3000);
    send(2, "Status");
    send(2, "Program");
    return std::move(s_);
  }

 private:
  void new_step() { ++step_; }
  int send(int c, const std::string& text) {
    s_.entries.push_back({EntryKind::Send, c, text, 0, false});
    new_step();
    return step_;
  }
  void join(int c, const std::string& text) { s_.entries.push_back({EntryKind::Send, c, text, 0, true}); }
  void wait(long ms) {
    s_.entries.push_back({EntryKind::Advance, 1, "", ms});
    new_step();
  }
  void connect(int c) {
    s_.entries.push_back({EntryKind::Connect, c, ""});
    new_step();
    connected_[c] = true;
  }
  void reconnect(int c) {
    connect(c);
    send(c, "Hello p" + std::to_string(c));
  }
  void close(int c) {
    s_.entries.push_back({EntryKind::Close, c, ""});
    new_step();
    connected_[c] = false;
  }

  // A client to act: 1 mostly, 2 as the other; one that is connected.
  int client() {
    if (!connected_[1] && !connected_[2]) reconnect(r_.chance(0.6) ? 1 : 2);
    if (!connected_[2]) return 1;
    if (!connected_[1]) return 2;
    return r_.chance(0.65) ? 1 : 2;
  }

  std::string point_words(bool with_z_word) {
    std::string s;
    for (std::size_t a = 0; a < m_.letters.size(); ++a) {
      const char l = m_.letters[a];
      double v;
      if (l == 'Z') v = r_.coord(m_.start[a] - 5, m_.start[a] + 25);
      else if (l == 'X' || l == 'Y') v = r_.coord(m_.start[a] - 30, m_.start[a] + 30);
      else v = r_.coord(m_.start[a] - 20, m_.start[a] + 20);
      s += with_z_word ? std::string(" ") + l + num(v) : " " + num(v);
    }
    return s;
  }

  std::string goto_line() {
    std::string s = "GoTo";
    for (int c = 0; c < 3; ++c) {
      const int a = static_cast<int>(m_.letters.find("XYZ"[c]));
      if (a < 0) {
        s += " 0";
        continue;
      }
      s += " " + num(c == 2 ? r_.coord(m_.start[a] - 5, m_.start[a] + 25) : r_.coord(m_.start[a] - 30, m_.start[a] + 30));
    }
    return s;
  }

  void upload(int c) {
    Program p = random_program(m_, r_, ++programs_);
    send(c, "Upload " + p.name);
    for (const auto& l : p.lines) join(c, l);
    join(c, ".");
    s_.programs[p.name] = p;
  }

  void bad_load(int c) {
    const BadProgram& b = bad_[static_cast<std::size_t>(r_.pick(0, static_cast<int>(bad_.size()) - 1))];
    BadLoadProbe probe;
    probe.before = send(c, "Status");
    if (!b.load.empty()) {
      probe.load = send(c, "Load " + b.load);
    } else {
      probe.load = send(c, "Upload " + b.name);
      for (const auto& l : b.lines) join(c, l);
      join(c, ".");
    }
    wait(300);
    probe.after = send(c, "Status");
    s_.probes.push_back(probe);
  }

  void jog(int c) {
    if (m_.xyz()) {
      static const char* dirs[] = {"10 0 0", "-10 0 0", "0 10 0", "0 -10 0", "0 0 10", "7 -7 0"};
      send(c, std::string("StartMv ") + dirs[r_.pick(0, 5)]);
      wait(r_.pick(50, 1500));
      send(c, "StartMv 0 0 0");
    } else {
      const char a = m_.letters[static_cast<std::size_t>(r_.pick(0, static_cast<int>(m_.letters.size()) - 1))];
      send(c, std::string("JogAx ") + a + (r_.chance(0.5) ? "" : "-") + std::to_string(r_.pick(5, 15)));
      wait(r_.pick(50, 1500));
      send(c, std::string("JogAx ") + a + "0");
    }
  }

  void motion(int c) {
    const int k = r_.pick(0, 99);
    if (k < 15) {
      send(c, "MoveTo 9" + point_words(true) + " F" + std::to_string(r_.pick(10, 40)));
    } else if (k < 25) {  // a queue of moves in one write: the planner holds its tail back
      send(c, "MoveTo 1" + point_words(true) + " F" + std::to_string(r_.pick(10, 40)));
      for (int i = r_.pick(2, 5); i > 0; --i) join(c, "MoveTo " + std::to_string(i + 1) + point_words(true) + " F" + std::to_string(r_.pick(10, 40)));
    }
    else if (k < 45) send(c, goto_line());
    else if (k < 70) jog(c);
    else if (k < 78) send(c, "Dwell 9 0." + std::to_string(r_.pick(1, 5)));
    else if (k < 88) send(c, "SetOut 9 " + (m_.outputs.empty() ? std::string("probe") : m_.outputs[0]) + (r_.chance(0.5) ? " on" : " off"));
    else if (k < 95) send(c, "Free");
    else send(c, "Home");
  }

  void action() {
    const int k = r_.pick(0, 999);
    const int c = client();
    if (k < 330) {  // wait: a cycle or two, a part of a move, a whole program
      const int w = r_.pick(0, 9);
      wait(w < 3 ? r_.pick(1, 50) : w < 7 ? r_.pick(50, 1000) : r_.pick(1000, 6000));
      if (w >= 7 && r_.chance(0.5)) send(c, "Status");  // where a program that ran to its end left it
    } else if (k < 430) {
      const int how = r_.pick(0, 9);
      if (how < 2) send(c, r_.chance(0.5) ? "StopMv" : "Abort");  // a stop and a Run in one write:
      if (how < 2) join(c, "Status");                              // the Run comes after the stop
      else send(c, "Status");  // where the machine stands as the run starts (MRM is incremental)
      join(c, r_.chance(0.4) ? "Run detached" : "Run");
      if (r_.chance(0.25)) {  // its client leaves while it runs
        wait(r_.pick(1, 1500));
        close(c);
      } else if (r_.chance(0.4)) {  // time to run to its end (or to its M0, and on after a Resume)
        wait(r_.pick(6000, 14000));
        send(c, "Status");
        if (r_.chance(0.5)) {
          send(c, "Resume");
          wait(r_.pick(3000, 8000));
          send(c, "Status");
        }
      }
    } else if (k < 465) {
      send(c, "Pause");
    } else if (k < 520) {
      send(c, "Resume");
    } else if (k < 550) {
      send(c, "Abort");
    } else if (k < 580) {
      send(c, "StopMv");
    } else if (k < 720) {
      motion(c);
    } else if (k < 800) {
      send(c, r_.chance(0.5) ? "Program" : "Status");
    } else if (k < 850) {  // a disconnect, or the reconnect of one that left
      const int who = r_.chance(0.7) ? 1 : 2;
      if (connected_[who]) close(who);
      else reconnect(who);
    } else if (k < 885) {
      const int t = r_.pick(0, 9), other = c == 1 ? 2 : 1;
      if (t < 5) send(c, "Take");
      else if (t < 9 || !connected_[other]) send(c, "Release");
      else send(other, "Take force");
    } else if (k < 940) {
      bad_load(c);
    } else {
      upload(c);
    }
    if (!connected_[1] && !connected_[2] && r_.chance(0.5)) reconnect(1);
  }

  const MachineInfo& m_;
  Random r_;
  std::vector<BadProgram> bad_;
  Script s_;
  int step_ = 0;
  int programs_ = 0;
  std::map<int, bool> connected_{{1, true}, {2, false}, {3, false}};
};

// ---------------------------------------------------------------- what was received

struct Cmd {
  int client = 0, step = 0;
  std::string text;
  bool upload_head = false, upload_body = false, upload_end = false;
  bool load_end = false;  // the '.' of an accepted Upload: answered as a Load
  std::optional<std::string> reply;
  std::size_t reply_index = 0;
  std::string verb() const {
    if (load_end) return "Upload.";
    const auto w = words(text);
    return w.empty() ? "" : w[0];
  }
};

struct Line {
  int step = 0;
  long t = 0;  // virtual ms since the start
  std::string text;
  int client = 0;
  std::size_t index = 0;  // order of arrival in the whole session (comparable within one client)
};

struct Session {
  std::vector<Cmd> cmds;
  std::vector<Line> heard;  // client 3: every broadcast
  std::vector<Line> all;    // every line every client received
  std::vector<long> step_time;  // virtual ms at the end of each step
  std::vector<std::pair<int, int>> closes;  // step, client
  std::vector<std::string> problems;  // of the replay itself
};

Session read_session(const std::vector<Entry>& out, long period_us) {
  Session s;
  std::map<int, std::deque<std::size_t>> waiting;  // per client: commands not yet answered
  std::map<int, bool> in_upload;
  int step = -1;
  long t_us = 0, stamp = 0;
  bool advancing = false;
  for (const auto& e : out) {
    if (e.kind == EntryKind::Comment) continue;
    if (!observed(e)) {
      if (!(e.kind == EntryKind::Send && e.joined)) {
        ++step;
        advancing = false;
        if (e.kind == EntryKind::Send) t_us += period_us;  // one motion cycle per step
        if (e.kind == EntryKind::Advance) {
          const long end = t_us + e.ms * 1000;
          while (t_us < end) t_us += period_us;
          advancing = true;
        }
        s.step_time.push_back(t_us / 1000);
      }
      if (e.kind == EntryKind::Connect || e.kind == EntryKind::Close) {
        waiting[e.client].clear();
        in_upload[e.client] = false;
        if (e.kind == EntryKind::Close) s.closes.push_back({step, e.client});
      }
      if (e.kind == EntryKind::Send) {
        Cmd c;
        c.client = e.client;
        c.step = step;
        c.text = e.text;
        if (in_upload[e.client]) {
          if (e.text == ".") {
            c.upload_end = true;
            in_upload[e.client] = false;
          } else {
            c.upload_body = true;
          }
        } else if (starts(e.text, "Upload ")) {
          c.upload_head = true;
          in_upload[e.client] = true;
        }
        waiting[e.client].push_back(s.cmds.size());
        s.cmds.push_back(c);
      }
      continue;
    }
    if (e.kind == EntryKind::Time) {  // within the advance this test counted
      stamp = e.ms;
      const long before = s.step_time.size() > 1 ? s.step_time[s.step_time.size() - 2] : 0;
      if (!advancing || stamp < before || stamp > t_us / 1000)
        s.problems.push_back("step " + std::to_string(step) + ": lines at " + std::to_string(stamp) + " ms, the test counted " +
                             std::to_string(before) + " to " + std::to_string(t_us / 1000) + " ms");
      continue;
    }
    const long t = advancing ? stamp : t_us / 1000;
    const Line line{step, t, e.text, e.client, s.all.size()};
    s.all.push_back(line);
    if (e.client == 3) s.heard.push_back(line);
    if (!starts(e.text, "Ok ") && !starts(e.text, "Err ")) continue;  // an event
    auto& q = waiting[e.client];
    if (q.empty()) {
      s.problems.push_back("client " + std::to_string(e.client) + " got a reply to nothing: " + e.text);
      continue;
    }
    Cmd& c = s.cmds[q.front()];
    q.pop_front();
    c.reply = e.text;
    c.reply_index = line.index;
    if (c.upload_head && starts(e.text, "Ok Upload")) {  // its lines get no reply, its '.' that of a Load
      while (!q.empty() && s.cmds[q.front()].upload_body) q.pop_front();
      if (!q.empty() && s.cmds[q.front()].upload_end) s.cmds[q.front()].load_end = true;
    }
  }
  for (auto& [client, q] : waiting)
    if (!q.empty()) s.problems.push_back("client " + std::to_string(client) + ": " + s.cmds[q.front()].text + " never answered");
  return s;
}

// ---------------------------------------------------------------- the rules

struct Counts {
  int runs = 0, detached_runs = 0, ended_ok = 0, end_pose_checked = 0;
  int aborted_by_stopmv = 0, aborted_by_abort = 0, aborted_by_disconnect = 0, aborted_other = 0;
  int detached_survived_disconnect = 0;
  int refused_202 = 0, refused_209 = 0;
  int bad_refused_213 = 0, bad_probe_position_checked = 0;
  int m0_pauses = 0, statuses_checked = 0, program_replies_checked = 0;
  int braking_checked = 0, stops_checked = 0;
  long braking_max_ms = 0, virtual_ms = 0;

  void add(const Counts& o) {
    runs += o.runs;
    detached_runs += o.detached_runs;
    ended_ok += o.ended_ok;
    end_pose_checked += o.end_pose_checked;
    aborted_by_stopmv += o.aborted_by_stopmv;
    aborted_by_abort += o.aborted_by_abort;
    aborted_by_disconnect += o.aborted_by_disconnect;
    aborted_other += o.aborted_other;
    detached_survived_disconnect += o.detached_survived_disconnect;
    refused_202 += o.refused_202;
    refused_209 += o.refused_209;
    bad_refused_213 += o.bad_refused_213;
    bad_probe_position_checked += o.bad_probe_position_checked;
    m0_pauses += o.m0_pauses;
    statuses_checked += o.statuses_checked;
    program_replies_checked += o.program_replies_checked;
    braking_checked += o.braking_checked;
    stops_checked += o.stops_checked;
    virtual_ms += o.virtual_ms;
    braking_max_ms = std::max(braking_max_ms, o.braking_max_ms);
  }
  std::string text() const {
    std::ostringstream o;
    o << "runs " << runs << " (detached " << detached_runs << "), ProgEnd ok " << ended_ok << " (end pose checked "
      << end_pose_checked << "), aborted by StopMv " << aborted_by_stopmv << " / Abort " << aborted_by_abort
      << " / disconnect " << aborted_by_disconnect << " / Release or Take force " << aborted_other
      << ", detached runs that outlived their controller " << detached_survived_disconnect << ", refused while running: Err 202 "
      << refused_202 << " / Err 209 " << refused_209 << ", bad programs refused with Err 213 " << bad_refused_213
      << " (position checked " << bad_probe_position_checked << "), M0 pauses " << m0_pauses << ", Status checked "
      << statuses_checked << ", Program checked " << program_replies_checked << ", stops " << stops_checked << ", program stops timed " << braking_checked
      << " (longest " << braking_max_ms << " ms to stand); " << virtual_ms / 1000 << " s of virtual time";
    return o.str();
  }
};

// The verbs refused while a program runs (docs/protocol.md, Run), and the '.' of an Upload.
const std::set<std::string> kRefusedWhileRunning = {"StartMv", "JogAx",  "GoTo",  "Home",   "HandMv", "Free",
                                                    "Reset",   "ForcePt", "MoveTo", "ArcTo", "Dwell",  "Probe",
                                                    "SetOut",  "Load",    "Run",    "Upload."};

constexpr long kStandWithinMs = 3000;  // generous: the machines here brake from full speed in well under 1 s
constexpr double kEndPoseTolerance = 0.01;
constexpr double kHomingOverrun = 5.0;  // the reference search brakes past the switch at a travel's end

struct RunSpan {
  int start = 0;             // step of the Run
  int end = -1;              // step of its ProgEnd (-1: none)
  int client = 0;
  bool detached = false;
  std::string name;
  std::vector<double> start_pos;
  std::vector<std::string> progend;  // its words
};

struct Stop {
  int step;
  std::size_t cmd;  // the command that stopped (its index in Session::cmds), or npos: a disconnect
  std::string who;  // as ProgEnd names it
};

constexpr std::size_t kNoCmd = static_cast<std::size_t>(-1);

class Checker {
 public:
  Checker(const MachineInfo& m, const Script& script, const Session& s) : m_(m), script_(script), s_(s) {}

  std::vector<std::string> problems;
  Counts counts;

  void run() {
    problems = s_.problems;
    controllers();
    runs();
    stop_list();
    refusals();
    stops();
    nothing_moves_after_a_stop();
    loaded_program();
    bad_loads();
    travel();
    ended_ok();
  }

 private:
  void fail(const std::string& what) { problems.push_back(what); }

  // Control as the observer heard it: who held it after each step (0 none, -1 unknown).
  void controllers() {
    int holder = 0;
    std::size_t i = 0;
    for (int step = 0; step < static_cast<int>(s_.step_time.size()); ++step) {
      for (; i < s_.heard.size() && s_.heard[i].step <= step; ++i) {
        const auto w = words(s_.heard[i].text);
        if (w.size() >= 2 && w[0] == "Control") holder = w[1] == "none" ? 0 : w[1] == "p1" ? 1 : w[1] == "p2" ? 2 : -1;
      }
      holder_after_.push_back(holder);
    }
  }
  int holder_before(int step) const { return step == 0 ? 0 : holder_after_[static_cast<std::size_t>(step - 1)]; }

  // Whether the line `l` (heard by client 3) came before command `c`'s reply: compared in
  // the stream of c's client, which heard both (events are never held back behind replies).
  bool heard_before_reply(const Line& l, const Cmd& c) const {
    if (l.step != c.step) return l.step < c.step;
    for (const auto& x : s_.all)
      if (x.client == c.client && x.step == l.step && x.text == l.text) return x.index < c.reply_index;
    return false;
  }

  // Rule 1: Ok Run and ProgEnd alternate.
  void runs() {
    std::vector<const Cmd*> run_cmds;
    for (std::size_t i = 0; i < s_.cmds.size(); ++i) {
      const Cmd& c = s_.cmds[i];
      if (c.verb() != "Run" || !c.reply || !starts(*c.reply, "Ok Run ")) continue;
      RunSpan r{c.step, -1, c.client, c.text == "Run detached", words(*c.reply)[2], {}, {}};
      if (i > 0 && s_.cmds[i - 1].step == c.step && s_.cmds[i - 1].reply)
        if (auto st = parse_status(*s_.cmds[i - 1].reply)) r.start_pos = st->pos;
      runs_.push_back(r);
      run_cmds.push_back(&c);
      ++counts.runs;
      if (r.detached) ++counts.detached_runs;
    }
    std::size_t next = 0;
    RunSpan* open = nullptr;
    for (const auto& l : s_.heard) {
      const auto w = words(l.text);
      if (w.empty() || (w[0] != "ProgEnd" && w[0] != "ProgPause")) continue;
      while (next < runs_.size() && (runs_[next].start < l.step || (runs_[next].start == l.step && !heard_before_reply(l, *run_cmds[next])))) {
        if (open) fail("step " + std::to_string(runs_[next].start) + ": Ok Run " + runs_[next].name + " while " + open->name + " (run at step " + std::to_string(open->start) + ") had no ProgEnd");
        open = &runs_[next++];
      }
      if (w[0] == "ProgPause") {
        if (!open) fail("step " + std::to_string(l.step) + ": " + l.text + " without a run");
        else ++counts.m0_pauses;
        continue;
      }
      if (!open) {
        fail("step " + std::to_string(l.step) + ": " + l.text + " without a run");
        continue;
      }
      if (w.size() < 5 || w[1] != open->name)
        fail("step " + std::to_string(l.step) + ": " + l.text + " does not end " + open->name);
      open->end = l.step;
      open->progend = w;
      open = nullptr;
    }
    for (; next < runs_.size(); ++next) {
      if (open) fail("step " + std::to_string(runs_[next].start) + ": Ok Run " + runs_[next].name + " while " + open->name + " had no ProgEnd");
      open = &runs_[next];
    }
    for (const auto& r : runs_)
      if (r.end < 0) fail("the run of " + r.name + " at step " + std::to_string(r.start) + " never got its ProgEnd");
  }

  const RunSpan* run_on(int step) const {  // a run that was on during the step (a part of it)
    for (const auto& r : runs_)
      if (r.start < step && (r.end < 0 || step <= r.end)) return &r;
    return nullptr;
  }

  // Every stop: StopMv and Abort from anyone, Release by the controller, Take force over
  // another, the controller's disconnect (not while a detached run is on: it goes on).
  void stop_list() {
    for (std::size_t i = 0; i < s_.cmds.size(); ++i) {
      const Cmd& c = s_.cmds[i];
      const int holder = holder_before(c.step);
      if (c.text == "StopMv") stops_.push_back({c.step, i, "StopMv"});
      else if (c.text == "Abort") stops_.push_back({c.step, i, "Abort"});
      else if (c.text == "Release" && holder == c.client) stops_.push_back({c.step, i, "released control"});
      else if (c.text == "Take force" && holder > 0 && holder != c.client) stops_.push_back({c.step, i, "Take force"});
    }
    for (const auto& [step, client] : s_.closes) {
      if (holder_before(step) != client) continue;
      const RunSpan* r = run_on(step);
      if (r && r->detached) {
        if (step == r->end) fail("step " + std::to_string(step) + ": the detached run of " + r->name + " ended as its controller p" + std::to_string(client) + " left: " + join(r->progend));
        else ++counts.detached_survived_disconnect;
        continue;
      }
      stops_.push_back({step, kNoCmd, "disconnected"});
    }
    std::sort(stops_.begin(), stops_.end(), [](const Stop& a, const Stop& b) { return a.step < b.step || (a.step == b.step && a.cmd < b.cmd); });
  }

  // A stop sent before command i in the same write (it acted first).
  bool stop_before_in_step(std::size_t i) const {
    for (const auto& st : stops_)
      if (st.step == s_.cmds[i].step && st.cmd != kNoCmd && st.cmd < i && s_.cmds[st.cmd].client == s_.cmds[i].client) return true;
    return false;
  }

  // Rule 2: nothing moves the machine beside the program.
  void refusals() {
    for (std::size_t i = 0; i < s_.cmds.size(); ++i) {
      const Cmd& c = s_.cmds[i];
      if (!kRefusedWhileRunning.count(c.verb()) || !c.reply) continue;
      const RunSpan* r = run_on(c.step);
      if (!r || (c.step == r->end && stop_before_in_step(i))) continue;
      if (starts(*c.reply, "Err 202 ")) ++counts.refused_202;
      else if (starts(*c.reply, "Err 209 ")) ++counts.refused_209;
      else fail("step " + std::to_string(c.step) + ": client " + std::to_string(c.client) + " '" + c.text + "' while " + r->name +
                " ran (from step " + std::to_string(r->start) + "): " + *c.reply);
    }
  }

  // Rules 3 and 4: what stops a run, and that the machine then stands.
  void stops() {
    for (const auto& r : runs_) {
      const Stop* first = nullptr;
      for (const auto& st : stops_)
        if (st.step > r.start) {
          first = &st;
          break;
        }
      const bool aborted = r.progend.size() >= 5 && r.progend[2] == "aborted";
      if (r.progend.size() >= 5 && r.progend[2] == "failed")
        fail("step " + std::to_string(r.end) + ": a valid program failed: " + join(r.progend));
      if (first && (r.end < 0 || first->step <= r.end)) {
        if (r.end != first->step || !aborted) {
          fail("step " + std::to_string(first->step) + ": " + first->who + " while " + r.name + " ran, but its ProgEnd came at step " +
               std::to_string(r.end) + ": " + join(r.progend));
          continue;
        }
        const std::string who = join(std::vector<std::string>(r.progend.begin() + 4, r.progend.end()));
        if (who != first->who) fail("step " + std::to_string(r.end) + ": ProgEnd names '" + who + "', the stop was " + first->who);
        if (who == "StopMv") ++counts.aborted_by_stopmv;
        else if (who == "Abort") ++counts.aborted_by_abort;
        else if (who == "disconnected") ++counts.aborted_by_disconnect;
        else ++counts.aborted_other;
        stands_after(*first, r.name);
      } else if (aborted) {
        fail("step " + std::to_string(r.end) + ": " + join(r.progend) + " with no stop in that step");
      }
    }
  }

  // The step of the first command that moves (or Run) accepted after the stop; past the end
  // when none was.
  int first_motion_after(const Stop& st) const {
    static const std::set<std::string> moving = {"StartMv", "JogAx", "GoTo", "Home", "HandMv", "MoveTo", "ArcTo",
                                                 "Dwell",   "Probe", "SetOut", "Run"};
    for (std::size_t i = 0; i < s_.cmds.size(); ++i) {
      const Cmd& c = s_.cmds[i];
      if (c.step < st.step || (c.step == st.step && (st.cmd == kNoCmd || i <= st.cmd))) continue;
      if (moving.count(c.verb()) && c.reply && starts(*c.reply, "Ok")) return c.step;
    }
    return static_cast<int>(s_.step_time.size());
  }

  // Rule 3, for every stop (a program's or not): after it nothing moves until a command
  // that moves (or a Run) is accepted after it.
  void nothing_moves_after_a_stop() {
    for (const auto& st : stops_) {
      const int until = first_motion_after(st);
      for (const auto& l : s_.heard) {
        if (l.step < st.step || l.step >= until) continue;
        const auto w = words(l.text);
        if (w.size() == 2 && w[0] == "State" && w[1] != "stopping" && w[1] != "idle" && w[1] != "free" && w[1] != "retract") {
          fail("step " + std::to_string(l.step) + ": State " + w[1] + " after the " + st.who + " of step " + std::to_string(st.step) +
               " with no motion accepted since");
          break;
        }
      }
      ++counts.stops_checked;
    }
  }

  // The machine stands (State idle or free) within kStandWithinMs of the stop that aborted
  // a run; judged up to the next motion accepted after the stop (a GoTo while it brakes
  // starts once it stands, a Run in the same write as the stop cannot be told apart).
  void stands_after(const Stop& st, const std::string& name) {
    const int until = first_motion_after(st);
    if (until == st.step) return;
    std::string mode = initial_mode();
    for (const auto& l : s_.heard) {
      if (l.step > st.step) break;
      const auto w = words(l.text);
      if (w.size() == 2 && w[0] == "State") mode = w[1];
    }
    const long t0 = s_.step_time[static_cast<std::size_t>(st.step)];
    if (mode == "idle" || mode == "free") {
      ++counts.braking_checked;
      return;
    }
    for (const auto& l : s_.heard) {
      if (l.step <= st.step || l.step >= until) continue;
      const auto w = words(l.text);
      if (w.size() != 2 || w[0] != "State" || w[1] == "stopping") continue;
      if (w[1] != "idle" && w[1] != "free") {
        fail("step " + std::to_string(st.step) + ": after " + name + " was aborted the machine went on to State " + w[1] + " at " + std::to_string(l.t) + " ms");
        return;
      }
      ++counts.braking_checked;
      counts.braking_max_ms = std::max(counts.braking_max_ms, l.t - t0);
      if (l.t - t0 > kStandWithinMs)
        fail("step " + std::to_string(st.step) + ": aborted at " + std::to_string(t0) + " ms, the machine stood only at " + std::to_string(l.t) + " ms");
      return;
    }
    const long t_until = until < static_cast<int>(s_.step_time.size()) ? s_.step_time[static_cast<std::size_t>(until)] : s_.step_time.back();
    if (t_until - t0 > kStandWithinMs)
      fail("step " + std::to_string(st.step) + ": after " + name + " was aborted the machine did not stand within " + std::to_string(kStandWithinMs) + " ms (State " + mode + ")");
  }

  std::string initial_mode() const {
    for (const auto& c : s_.cmds)
      if (c.reply)
        if (auto st = parse_status(*c.reply)) return st->state;
    return "idle";
  }

  // Rule 5 (the name): every Program reply names the last program that loaded; its state
  // says running or paused exactly while a run is on.
  void loaded_program() {
    std::string loaded = "none";
    for (const auto& c : s_.cmds) {
      if (!c.reply) continue;
      const auto w = words(*c.reply);
      if (w.size() >= 3 && w[0] == "Ok" && w[1] == "Load") loaded = w[2];
      if ((c.verb() == "Load" || c.verb() == "Upload.") && starts(*c.reply, "Err 213 ")) ++counts.bad_refused_213;
      if (c.text != "Program" || w.size() < 4 || w[1] != "Program") continue;
      ++counts.program_replies_checked;
      if (w[2] != loaded) fail("step " + std::to_string(c.step) + ": Program names " + w[2] + ", the last program loaded is " + loaded);
      const bool on = run_on(c.step) != nullptr, says_on = w[3] == "running" || w[3] == "paused";
      if (on != says_on) fail("step " + std::to_string(c.step) + ": " + *c.reply + (on ? " while a run is on" : " with no run on"));
    }
  }

  const Cmd* command_at(int step) const {  // the first command sent in a step
    for (const auto& c : s_.cmds)
      if (c.step == step) return &c;
    return nullptr;
  }

  // Rule 5 (refused, nothing moved): the probes around each program that does not fit.
  void bad_loads() {
    for (const auto& p : script_.probes) {
      // What speaks for the program: the Load's reply, the '.' of an accepted Upload, or the
      // refusal of the Upload itself.
      const Cmd* answer = nullptr;
      for (const auto& c : s_.cmds)
        if (c.step == p.load && (c.verb() == "Load" || c.load_end || (c.upload_head && c.reply && starts(*c.reply, "Err "))))
          answer = &c;
      if (!answer || !answer->reply) {
        fail("step " + std::to_string(p.load) + ": no answer to a program that does not fit");
        continue;
      }
      const std::string& a = *answer->reply;
      if (!(starts(a, "Err 213 ") || starts(a, "Err 202 ") || starts(a, "Err 209 ")))
        fail("step " + std::to_string(p.load) + ": a program that does not fit answered " + a);
      const Cmd* before = command_at(p.before);
      const Cmd* after = command_at(p.after);
      if (!before || !after || !before->reply || !after->reply) continue;
      const auto b = parse_status(*before->reply), f = parse_status(*after->reply);
      if (!b || !f || (b->state != "idle" && b->state != "free") || run_on(p.load)) continue;
      ++counts.bad_probe_position_checked;
      bool moved = f->state != "idle" && f->state != "free";
      for (std::size_t i = 0; i < b->pos.size() && i < f->pos.size(); ++i) moved |= std::abs(b->pos[i] - f->pos[i]) > 0.03;
      if (moved) fail("step " + std::to_string(p.load) + ": the machine moved around a program that does not fit: " + *before->reply + " / " + *after->reply);
    }
  }

  // Rule 6.
  void travel() {
    bool homing_started = false;
    for (const auto& c : s_.cmds) {
      if (!c.reply) continue;
      if (c.text == "Home" && starts(*c.reply, "Ok")) homing_started = true;
      const auto st = parse_status(*c.reply);
      if (!st) continue;
      ++counts.statuses_checked;
      if (st->pos.size() != m_.letters.size()) {
        fail("step " + std::to_string(c.step) + ": a Status of " + std::to_string(st->pos.size()) + " axes: " + *c.reply);
        continue;
      }
      // The reference search runs past a travel's end to its switch; stopped there, the
      // machine stands outside until referenced (the soft limits hold from then on).
      const bool overrun = st->state == "home" || (homing_started && c.reply->find(" Referenced no ") != std::string::npos);
      const double slack = overrun ? kHomingOverrun : 0.0005;  // printed to 3 decimals
      for (std::size_t a = 0; a < st->pos.size(); ++a)
        if (st->pos[a] < m_.travel_min[a] - slack || st->pos[a] > m_.travel_max[a] + slack)
          fail("step " + std::to_string(c.step) + ": axis " + std::string(1, m_.letters[a]) + " outside its travel [" +
               num(m_.travel_min[a]) + ", " + num(m_.travel_max[a]) + "]: " + *c.reply);
    }
  }

  // Rule 7.
  void ended_ok() {
    for (const auto& r : runs_) {
      if (r.progend.size() < 5 || r.progend[2] != "ok") continue;
      ++counts.ended_ok;
      auto it = script_.programs.find(r.name);
      if (it == script_.programs.end()) {
        fail("ProgEnd ok of a program the test never sent: " + join(r.progend));
        continue;
      }
      const Program& p = it->second;
      const int n_lines = static_cast<int>(p.lines.size());
      const int end_line = std::atoi(r.progend[3].c_str());
      if (end_line < p.last_motion_line || end_line > n_lines)
        fail(join(r.progend) + ": its last motion is line " + std::to_string(p.last_motion_line) + " of " + std::to_string(n_lines));
      int previous = 0;
      for (const auto& l : s_.heard) {
        if (l.step < r.start || l.step > r.end) continue;
        const auto w = words(l.text);
        if (w.size() != 4 || w[0] != "Block" || w[1] != r.name) continue;
        const int line = std::atoi(w[2].c_str());
        if (line < previous || line < 1 || line > n_lines) fail("step " + std::to_string(l.step) + ": " + l.text + " after line " + std::to_string(previous) + " of " + std::to_string(n_lines));
        previous = line;
      }
      if (previous == 0) fail(r.name + " ended ok without a Block");
      // Where it stands: the first Status after the ProgEnd with nothing moving in between.
      const Cmd* status = nullptr;
      for (const auto& c : s_.cmds) {
        if (c.step <= r.end) continue;
        if (kRefusedWhileRunning.count(c.verb()) && (!c.reply || starts(*c.reply, "Ok"))) break;
        if (c.reply && parse_status(*c.reply)) {
          status = &c;
          break;
        }
      }
      if (!status) continue;
      const auto st = parse_status(*status->reply);
      std::vector<double> want = p.end;
      if (p.relative) {
        if (r.start_pos.size() != want.size()) {
          fail(r.name + ": no Status with its Run");
          continue;
        }
        for (std::size_t a = 0; a < want.size(); ++a) want[a] += r.start_pos[a];
      }
      ++counts.end_pose_checked;
      for (std::size_t a = 0; a < want.size() && a < st->pos.size(); ++a) {
        if (std::isnan(want[a])) continue;
        if (std::abs(st->pos[a] - want[a]) > kEndPoseTolerance + 0.0005)
          fail("step " + std::to_string(status->step) + ": " + r.name + " ended ok, axis " + std::string(1, m_.letters[a]) + " at " +
               num(st->pos[a]) + ", the program ends at " + num(want[a]) + ": " + *status->reply);
      }
    }
  }

  static std::string join(const std::vector<std::string>& w) {
    std::string s;
    for (const auto& x : w) s += (s.empty() ? "" : " ") + x;
    return s;
  }

  const MachineInfo& m_;
  const Script& script_;
  const Session& s_;
  std::vector<int> holder_after_;
  std::vector<RunSpan> runs_;
  std::vector<Stop> stops_;
};

constexpr int kActions = 70;

}  // namespace

TEST_CASE("program runner properties: random sessions on every configuration that runs programs", "[long]") {
  const auto configs = program_configs();
  // The six shipped today; a new one with a "programs" section joins by itself.
  REQUIRE(configs.size() >= 6);
  Counts total;
  std::string summary;  // what each machine showed: printed at the end
  for (const auto& config : configs) {
    const MachineInfo m = machine_info(config);
    Counts per_config;
    for (const std::uint64_t seed : property_seeds({1, 2, 3, 4, 5, 6})) {
      INFO(config << " seed " << seed << " (IMESS_PROPERTY_SEEDS=\"" << seed << "\" runs it alone)");
      Generator gen(m, mixed_seed(seed, config));
      const Script script = gen.make(kActions);
      std::vector<Entry> out;
      try {
        out = replay(script.entries, config + " seed " + std::to_string(seed));
      } catch (const std::exception& e) {
        const auto path = std::filesystem::temp_directory_path() /
                          ("imess-program-properties-" + std::filesystem::path(config).stem().string() + "-" + std::to_string(seed) + ".txt");
        std::ofstream(path) << format_transcript(script.entries);
        FAIL("messd's parts threw while replaying (the script: " << path.string() << "): " << e.what());
      }
      const Session session = read_session(out, m.period_us);
      Checker check(m, script, session);
      check.run();
      check.counts.virtual_ms = session.step_time.empty() ? 0 : session.step_time.back();
      if (!check.problems.empty()) {
        const auto path = std::filesystem::temp_directory_path() /
                          ("imess-program-properties-" + std::filesystem::path(config).stem().string() + "-" + std::to_string(seed) + ".txt");
        std::ofstream(path) << numbered(out);
        std::string first;
        for (std::size_t i = 0; i < check.problems.size() && i < 8; ++i) first += "\n  " + check.problems[i];
        FAIL_CHECK(check.problems.size() << " rule(s) broken; the transcript: " << path.string() << first);
      }
      per_config.add(check.counts);
    }
    INFO(config << ": " << per_config.text());
    summary += config + ": " + per_config.text() + "\n";
    // Every rule was exercised on this machine.
    CHECK(per_config.runs > 0);
    CHECK(per_config.detached_runs > 0);
    CHECK(per_config.end_pose_checked > 0);
    CHECK(per_config.aborted_by_stopmv > 0);
    CHECK(per_config.aborted_by_abort > 0);
    CHECK(per_config.aborted_by_disconnect > 0);
    CHECK(per_config.detached_survived_disconnect > 0);
    CHECK(per_config.refused_202 > 0);
    CHECK(per_config.bad_refused_213 > 0);
    CHECK(per_config.bad_probe_position_checked > 0);
    CHECK(per_config.braking_checked > 0);
    CHECK(per_config.statuses_checked > 0);
    CHECK(per_config.program_replies_checked > 0);
    total.add(per_config);
  }
  WARN(summary << "all: " << total.text());
  CHECK(total.refused_209 > 0);
  CHECK(total.m0_pauses > 0);
  CHECK(total.aborted_other > 0);
}
