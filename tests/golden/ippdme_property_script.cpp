// The I++ DME properties' sessions: for a seed, a random script of an inspection program on the
// I++ port beside a MESSD jog panel (the actions are listed in test_ippdme_properties.cpp's
// header). Only inputs: what messd answers is the rules' business (ippdme_property_rules.cpp).
#include "shipped_config.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <stdexcept>

#include "config_rig.hpp"
#include "golden_harness.hpp"
#include "ippdme_properties.hpp"
#include "property_support.hpp"

namespace imess::golden::ippdme_properties {

namespace {
using hal::Vec3;
}  // namespace

bool has_ipp_server(const std::string& config) {
  try {
    replay(parse_transcript("@ " + config + "\n+2 ipp\n", config), config);
    return true;
  } catch (const std::exception& e) {
    if (std::string(e.what()).find("no I++ DME server") != std::string::npos) return false;
    throw;
  }
}

Machine machine_of(const std::string& config) {
  Machine m;
  m.config = config;
  test::ConfigRig rig(std::string(IMESS_SOURCE_DIR) + "/" + config);
  const auto& cfg = rig.config();
  std::string letters;
  for (int a = 0; a < cfg.core.layout.count; ++a) letters += cfg.core.layout.letters[a];
  for (int c = 0; c < 3; ++c) {
    m.axis[c] = static_cast<int>(letters.find("XYZ"[c]));
    if (m.axis[c] < 0) throw std::runtime_error(config + ": no " + std::string(1, "XYZ"[c]) + " axis");
    m.lo[c] = cfg.core.axes[m.axis[c]].travel_min;
    m.hi[c] = cfg.core.axes[m.axis[c]].travel_max;
  }
  m.tip = cfg.core.params.tip_radius;
  m.scene = cfg.sim.scene;
  m.period_us = static_cast<long>(std::lround(cfg.period_us));
  double top = m.lo[2];
  for (const auto& s : m.scene.solids())
    if (const auto* b = std::get_if<sim::BoxSolid>(&s)) top = std::max(top, b->center.z() + b->size.z() / 2);
    else if (const auto* p = std::get_if<sim::PlaneSolid>(&s)) top = std::max(top, p->point.z());
  m.safe_z = std::min(top + 30, m.hi[2]);
  m.centre = {(m.lo[0] + m.hi[0]) / 2, (m.lo[1] + m.hi[1]) / 2, m.lo[2]};
  for (const auto& s : m.scene.solids())
    if (const auto* b = std::get_if<sim::BoxSolid>(&s)) {
      m.centre = b->center;
      break;
    }
  const auto out = replay(parse_transcript("@ " + config + "\n> Status\n", config), config);
  for (const auto& e : out)
    if (e.kind == EntryKind::Receive && parse_status(e.text)) m.referenced = e.text.find(" Referenced yes ") != std::string::npos;
  return m;
}

std::vector<std::string> ipp_configs() {
  std::vector<std::string> out;
  for (const auto& f : std::filesystem::directory_iterator(std::string(IMESS_SOURCE_DIR) + "/config"))
    if (f.path().extension() == ".json" && imess::test::simulated_config(f.path()) && has_ipp_server("config/" + f.path().filename().string()))
      out.push_back("config/" + f.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

namespace {

// ---------------------------------------------------------------- points on the scene

struct Surface {
  Vec3 p, n;  // a point of a surface and its outward normal
};

Vec3 yawed(const sim::BoxSolid& b, const Vec3& local) {
  const double a = b.yaw_deg * M_PI / 180, c = std::cos(a), s = std::sin(a);
  return {c * local.x() - s * local.y(), s * local.x() + c * local.y(), local.z()};
}

// A point on a face of a box (top, the four sides, a bore's wall) or on a plane within the
// travel, kept only when the scene agrees it lies on the surface with free space before it
// (not on a fillet, a rim or inside another solid).
std::optional<Surface> surface_point(const Machine& m, Random& r) {
  // Boxes and planes only: the reference sphere on its stem is kept out of the scripts.
  std::vector<sim::Solid> solids;
  for (const auto& solid : m.scene.solids())
    if (std::holds_alternative<sim::BoxSolid>(solid) || std::holds_alternative<sim::PlaneSolid>(solid)) solids.push_back(solid);
  if (solids.empty()) return std::nullopt;
  for (int attempt = 0; attempt < 20; ++attempt) {
    const auto& solid = solids[static_cast<std::size_t>(r.pick(0, static_cast<int>(solids.size()) - 1))];
    Surface s;
    if (const auto* b = std::get_if<sim::BoxSolid>(&solid)) {
      const Vec3 h = b->size / 2;
      const int face = r.pick(0, b->bores.empty() ? 4 : 6);
      Vec3 local, n;
      if (face == 0) {
        local = {r.real(-h.x() + 3, h.x() - 3), r.real(-h.y() + 3, h.y() - 3), h.z()};
        n = Vec3::UnitZ();
      } else if (face <= 4) {
        const int axis = face <= 2 ? 0 : 1;
        const double sign = face % 2 ? -1 : 1;
        n = Vec3::Zero();
        n[axis] = sign;
        local = {r.real(-h.x() + 3, h.x() - 3), r.real(-h.y() + 3, h.y() - 3), r.real(-h.z() + 3, h.z() - 3)};
        local[axis] = sign * h[axis];
      } else {
        const auto& bore = b->bores[static_cast<std::size_t>(r.pick(0, static_cast<int>(b->bores.size()) - 1))];
        const double a = r.real(0, 2 * M_PI), radius = bore.diameter / 2;
        local = {bore.x + radius * std::cos(a), bore.y + radius * std::sin(a), r.real(-h.z() + 5, h.z() - 5)};
        n = {-std::cos(a), -std::sin(a), 0};
      }
      s = {b->center + yawed(*b, local), yawed(*b, n)};
    } else if (const auto* p = std::get_if<sim::PlaneSolid>(&solid)) {
      const Vec3 n = p->normal.normalized();
      const Vec3 q(r.real(m.lo[0], m.hi[0]), r.real(m.lo[1], m.hi[1]), r.real(m.lo[2], m.hi[2]));
      s = {q - n * n.dot(q - p->point), n};
    }
    if (std::abs(m.scene.distance(s.p)) < 1e-6 && m.scene.distance(s.p + s.n * (m.tip + 1)) > m.tip + 0.9) return s;
  }
  return std::nullopt;
}

class Generator {
 public:
  Generator(const Machine& m, std::uint64_t seed) : m_(m), r_(seed) {}

  Script make(int actions) {
    s_.entries.push_back({EntryKind::Config, 1, m_.config});
    step_ = 0;
    open_ipp();
    for (int i = 0; i < actions; ++i) action();
    // The end: stop what runs, leave, and show that messd still serves (rule 4).
    if (ipp_ == 0) open_ipp();
    send_ipp(etag() + " AbortE()");
    send_ipp(ctag() + " ClearAllErrors()");
    const std::string end = ctag();
    const int end_step = send_ipp(end + " EndSession()");
    wait(kRestWithinMs);
    probes_.push_back({RestProbe::End, ipp_, end_step, send(1, "Status"), end});
    s_.clean_clients.insert(ipp_);
    close_ipp();
    send(1, "Release");  // the panel may have taken over: control free for the new client
    wait(500);
    connect_ipp();
    s_.final_client = ipp_;
    send_ipp(ctag() + " StartSession()");
    send_ipp(ctag() + " SetCoordSystem(MachineCsy)");  // frames outlive sessions: read machine coordinates
    send_ipp(ctag() + " Get(X(), Y(), Z())");
    send_ipp(ctag() + " EndSession()");
    s_.final_status_step = send(1, "Status");
    s_.probes = probes_;
    return std::move(s_);
  }

 private:
  // -------------------------------------------------- script entries
  int send(int c, const std::string& text) {
    s_.entries.push_back({EntryKind::Send, c, text, 0, false});
    return ++step_;
  }
  void join(int c, const std::string& text) { s_.entries.push_back({EntryKind::Send, c, text, 0, true}); }
  int send_ipp(const std::string& text) { return send(ipp_, text); }
  void wait(long ms) {
    s_.entries.push_back({EntryKind::Advance, 1, "", ms});
    ++step_;
  }
  void connect_ipp() {
    ipp_ = next_client_++;
    s_.entries.push_back({EntryKind::Connect, ipp_, "ipp"});
    ++step_;
    s_.ipp_clients.insert(ipp_);
    in_session_ = false;
  }
  void open_ipp() {
    connect_ipp();
    send_ipp(ctag() + " StartSession()");
    in_session_ = true;
    if (r_.chance(0.5)) move_daemon();  // as inspection software shows the position
  }
  int close_ipp() {
    s_.entries.push_back({EntryKind::Close, ipp_, ""});
    ipp_ = 0;
    return ++step_;
  }

  // Tags count up as clients do; now and then one is sent again (rule 1: refused while open).
  std::string ctag() {
    cmd_ = cmd_ % 99999 + 1;
    return remember(zero_padded(cmd_, 5));
  }
  std::string etag() {
    evt_ = evt_ % 9999 + 1;
    return remember("E" + zero_padded(evt_, 4));
  }
  std::string remember(std::string tag) {
    recent_.push_back(tag);
    if (recent_.size() > 6) recent_.pop_front();
    return tag;
  }
  std::string reused_tag() { return recent_.empty() ? ctag() : recent_[static_cast<std::size_t>(r_.pick(0, static_cast<int>(recent_.size()) - 1))]; }

  // -------------------------------------------------- I++ commands
  double axis_value(int c, int how) {  // 0 near the work, 1 anywhere, 2 a travel end, 3 beyond it
    if (how == 0) return r_.coord(std::max(m_.lo[c], m_.centre[c] - 150), std::min(m_.hi[c], m_.centre[c] + 150));
    if (how == 1) return r_.coord(m_.lo[c], m_.hi[c]);
    if (how == 2) return r_.chance(0.5) ? m_.lo[c] : m_.hi[c];
    return r_.chance(0.5) ? m_.lo[c] - r_.coord(0.01, 400) : m_.hi[c] + r_.coord(0.01, 400);
  }

  std::string goto_line() {
    const int k = r_.pick(0, 19), how = k < 9 ? 0 : k < 12 ? 1 : k < 15 ? 2 : 3;
    std::string args;
    const int odd = r_.pick(0, 2);  // the axis a travel end or beyond is tried on
    for (int c = 0; c < 3; ++c) {
      if (c != odd && !r_.chance(0.7)) continue;
      const double v = axis_value(c, c == odd ? how : std::min(how, 1));
      args += std::string(args.empty() ? "" : ", ") + "XYZ"[c] + "(" + num(v) + ")";
    }
    return "GoTo(" + args + ")";
  }

  std::string xyz(const Vec3& p) { return "X(" + num(p.x(), 4) + "), Y(" + num(p.y(), 4) + "), Z(" + num(p.z(), 4) + ")"; }
  std::string ijk(const Vec3& n) { return "IJK(" + num(n.x(), 6) + ", " + num(n.y(), 6) + ", " + num(n.z(), 6) + ")"; }

  // A point to measure: on a surface after a move above it (queued in one write or step by
  // step), or straight from where the machine is, or in the air, or malformed.
  void ptmeas() {
    const int k = r_.pick(0, 99);
    const auto s = surface_point(m_, r_);
    if (k < 55 && s) {
      const Vec3 above = s->p + s->n * (m_.tip + r_.real(3, 8));
      const std::vector<std::string> lines = {
          "GoTo(Z(" + num(m_.safe_z) + "))",
          "GoTo(X(" + num(above.x()) + "), Y(" + num(above.y()) + "))",
          "GoTo(Z(" + num(above.z()) + "))",
          "PtMeas(" + xyz(s->p) + (r_.chance(0.7) ? ", " + ijk(s->n) : std::string()) + ")",
      };
      const bool queued = r_.chance(0.5);
      send_ipp(ctag() + " ClearAllErrors()");  // as a client does before a new feature
      for (const auto& line : lines) {
        if (queued) join(ipp_, ctag() + " " + line);
        else send_ipp(ctag() + " " + line);
        if (!queued && r_.chance(0.8)) wait(r_.pick(1000, 6000));
      }
      if (queued && r_.chance(0.8)) wait(r_.pick(4000, 15000));
    } else if (k < 70 && s) {
      send_ipp(ctag() + " PtMeas(" + xyz(s->p) + (r_.chance(0.5) ? ", " + ijk(s->n) : std::string()) + ")");
    } else if (k < 88) {  // in the air: no surface (1006), or into whatever is in the way
      const Vec3 p(axis_value(0, 0), axis_value(1, 0), r_.coord(m_.safe_z, std::max(m_.safe_z, m_.hi[2] - 50)));
      Vec3 n(r_.real(-1, 1), r_.real(-1, 1), r_.real(-1, 1));
      send_ipp(ctag() + " PtMeas(" + xyz(p) + (r_.chance(0.6) && n.norm() > 0.1 ? ", " + ijk(n.normalized()) : std::string()) + ")");
    } else {
      static const char* odd[] = {"PtMeas(X(460), Y(350), Z(80), IJK(0, 0, 0))", "PtMeas(IJK(0, 0, 1))", "PtMeas(Z(80))",
                                  "PtMeas(X(9999), IJK(1, 0, 0))", "PtMeas(X(460), Tool.A(3))"};
      send_ipp(ctag() + " " + odd[r_.pick(0, 4)]);
    }
  }

  std::string prop_path() {
    static const char* params[] = {"GoToPar.Speed", "GoToPar.Accel", "PtMeasPar.Speed", "PtMeasPar.Accel", "PtMeasPar.Approach",
                                   "PtMeasPar.Search", "PtMeasPar.Retract"};
    static const char* suffix[] = {"", ".Act", ".Min", ".Max", ".Def"};
    const int k = r_.pick(0, 19);
    if (k == 0) return "Tool.Name";
    if (k == 1) return "FoundTool.Name";
    if (k == 2) return "Tool.Nonsense";
    if (k == 3) return "Tool.GoToPar.Speed.Nope";
    return std::string("Tool.") + params[r_.pick(0, 6)] + suffix[r_.pick(0, 4)];
  }

  // A value for a parameter: mostly within its range, sometimes beyond (clamped, 0504), now and
  // then one so slow that only AbortE or a drop ends the move.
  std::string prop_setting() {
    struct P {
      const char* name;
      double lo, hi, out_lo, out_hi;
    };
    static const P params[] = {{"GoToPar.Speed", 20, 150, 0, 5000},     {"GoToPar.Accel", 100, 2000, -1, 1e6},
                               {"PtMeasPar.Speed", 1, 20, 0, 900},      {"PtMeasPar.Approach", 0.5, 10, 0, 300},
                               {"PtMeasPar.Search", 1, 15, -2, 150},    {"PtMeasPar.Retract", -1, 5, -9, 500}};
    const auto& p = params[r_.pick(0, 5)];
    const int k = r_.pick(0, 99);
    const double v = k < 80 ? r_.coord(p.lo, p.hi) : k < 97 ? p.out_hi : p.out_lo;
    return std::string("Tool.") + p.name + (r_.chance(0.1) ? ".Max" : "") + "(" + num(v) + ")";
  }

  void props() {
    const int k = r_.pick(0, 9);
    const int n = r_.pick(1, 3);
    std::string args;
    if (k < 5) {
      for (int i = 0; i < n; ++i) args += (i ? ", " : "") + prop_setting();
      send_ipp((k < 4 ? ctag() + " SetProp(" : etag() + " SetPropE(") + args + ")");
    } else {
      for (int i = 0; i < n; ++i) args += (i ? ", " : "") + prop_path() + "()";
      send_ipp((k < 9 ? ctag() + " GetProp(" : etag() + " GetPropE(") + args + ")");
    }
  }

  // Lines a client should not send: each is answered by the parser's error (rule 1).
  std::string garbage() {
    static const char* lines[] = {
        "0001 Get(X())",          "A0001 Get(X())",        "00000 Get(X())",           "E0000 AbortE()",
        "123456 Get(X())",        "@TAG GoTo(X(1))",       "",                         "  ",
        "%s GoTo(X(1)",           "%sGoTo(X(1))",          "%s goto(X(1))",            "%s Get(X()) ",
        "%s Get(W())",            "%s Get(IJK())",         "%s GoTo()",                "%s ScanOnLine(1,2,3)",
        "%s Get(X(), Y(1))",      "%s  Get(X())",          "%s GetErrStatusE()",       "%s AbortE()",
        "%s Get(X()\x01)",        "%s Get(X())\x7f",       "%s GoTo(X(1\xff))",        "\x1b[A",
        "%s Get(X())\rGet(Y())",  "%s Get(X())\t",         "%s StopDaemon(E0000)",     "%s GoTo(X(1e999))",
        "%s SetProp(Speed(3))",   "%s OnMoveReportE()",    "%s GetErrorInfo(12.5)",    "%s GoTo(X(1), X(2))",
        "012345 GoTo(X(3.1))",    "%s PtMeas(X(430), Y(330), Z(80), IJK(0,0,0))",
    };
    std::string line = lines[r_.pick(0, static_cast<int>(std::size(lines)) - 1)];
    if (const auto at = line.find("%s"); at != std::string::npos) line.replace(at, 2, r_.chance(0.8) ? ctag() : etag());
    return line;
  }

  void rest_probe(RestProbe::Kind kind, int trigger_step, const std::string& tag, int client) {
    wait(kRestWithinMs);
    probes_.push_back({kind, client, trigger_step, send(1, "Status"), tag});
  }

  // More lines in one write than one read of the server takes (4 KiB): queries, as a client
  // sends a batch of them; behind a move they fill the queue, and its flow control holds the
  // rest unread (rule 1 allows late answers then).
  void burst() {
    if (!kBurstsBeyondOneRead) return;
    send_ipp(ctag() + " Get(X(), Y(), Z())");
    for (int i = r_.pick(60, 120); i > 0; --i)
      join(ipp_, ctag() + (r_.chance(0.5) ? " Get(X(), Y(), Z())" : " GetProp(Tool.GoToPar.Speed(), Tool.PtMeasPar.Speed(), Tool.PtMeasPar.Approach())"));
  }

  // A move and more commands behind it than the server queues (64): its flow control stops
  // reading until the move ends. Short lines, one read: no burst.
  void fill_queue() {
    if (!kQueueBeyondItsLimit) return;
    send_ipp(ctag() + " " + goto_line());
    for (int i = r_.pick(64, 70); i > 0; --i) join(ipp_, ctag() + " Get(Z())");
  }

  // Coordinate systems and tools: a part frame moved and turned (theta beyond 180 now and
  // then: 1007), GoTo and Get in it; tools that measure, do not (NoTool) or do not exist.
  void frames_and_tools() {
    const int k = r_.pick(0, 9);
    if (k < 3) {
      const double theta = r_.chance(0.5) ? 0 : r_.chance(0.9) ? r_.coord(0, 180) : 200;
      send_ipp(ctag() + " SetCsyTransformation(" + (r_.chance(0.8) ? "PartCsy" : "MoveableMachineCsy") + ", " + num(r_.coord(-200, 200)) +
               ", " + num(r_.coord(-200, 200)) + ", " + num(r_.coord(-100, 100)) + ", " + num(theta) + ", " + num(r_.coord(-360, 720)) +
               ", " + num(r_.coord(-360, 720)) + ")");
    } else if (k < 6) {
      static const char* csy[] = {"MachineCsy", "MachineCsy", "PartCsy", "MoveableMachineCsy"};
      send_ipp(ctag() + " SetCoordSystem(" + csy[r_.pick(0, 3)] + ")");
    } else if (k < 7) {
      send_ipp(ctag() + (r_.chance(0.5) ? " GetCoordSystem()" : " GetCsyTransformation(PartCsy)"));
    } else {
      static const char* tools[] = {"\"RefTool\"", "\"RefTool\"", "\"NoTool\"", "\"Nope\""};
      static const char* verbs[] = {"ChangeTool", "ChangeTool", "SetTool", "FindTool", "GetChangeToolAction"};
      send_ipp(ctag() + " " + verbs[r_.pick(0, 4)] + "(" + tools[r_.pick(0, 3)] + ")");
    }
  }

  void move_daemon() {
    static const char* reports[] = {"Time(0.1), X(), Y(), Z()", "Time(0.05), Z()", "Dis(5), X(), Y(), Z()",
                                    "Time(1), Dis(2), Z(), X()", "X(), Y(), Z()", "Time(0.2), R()"};
    daemon_ = etag();
    send_ipp(daemon_ + " OnMoveReportE(" + reports[r_.pick(0, 5)] + ")");
  }

  void ipp_action() {
    const int k = r_.pick(0, 999);
    if (!in_session_ && r_.chance(0.8)) {
      send_ipp(ctag() + " StartSession()");
      in_session_ = true;
      return;
    }
    if (k < 150) {
      if (r_.chance(0.4)) {
        send_ipp(ctag() + " ClearAllErrors()");
        join(ipp_, ctag() + " " + goto_line());
      } else {
        send_ipp(ctag() + " " + goto_line());
      }
      if (r_.chance(0.5)) join(ipp_, ctag() + " Get(X(), Y(), Z())");  // where it arrived (rule 6)
    } else if (k < 300) {
      ptmeas();
    } else if (k < 390) {
      props();
    } else if (k < 450) {
      static const char* gets[] = {"Get(X(), Y(), Z())", "Get(Z())", "Get(Y(), X())", "Get(X(), X())", "Get(R())"};
      send_ipp(ctag() + " " + gets[r_.pick(0, 4)]);
    } else if (k < 540) {
      send_ipp(ctag() + " ClearAllErrors()");
    } else if (k < 600) {
      const std::string tag = etag();
      const int step = send_ipp(tag + " AbortE()");
      if (r_.chance(0.6)) rest_probe(RestProbe::Abort, step, tag, ipp_);
    } else if (k < 640) {
      static const char* user[] = {"EnableUser()", "DisableUser()", "IsUserEnabled()"};
      send_ipp(ctag() + " " + user[r_.pick(0, 2)]);
    } else if (k < 690) {
      const int d = r_.pick(0, 9);
      if (d < 5) {
        move_daemon();
      } else if (d < 8) {
        send_ipp(ctag() + " StopDaemon(" + (daemon_.empty() || r_.chance(0.2) ? std::string("E9999") : daemon_) + ")");
      } else {
        send_ipp(ctag() + " StopAllDaemons()");
      }
    } else if (k < 710) {
      send_ipp(r_.chance(0.5) ? etag() + " GetErrStatusE()" : ctag() + " GetXtdErrStatus()");
    } else if (k < 800) {
      send_ipp(garbage());
    } else if (k < 830) {  // a tag sent again: alone, or right behind a move that holds it open
      if (r_.chance(0.5)) {
        const std::string tag = ctag();
        send_ipp(tag + " " + goto_line());
        join(ipp_, tag + " Get(X())");
      } else {
        send_ipp(reused_tag() + " Get(X(), Y(), Z())");
      }
    } else if (k < 860) {
      const std::string tag = ctag();
      const int step = send_ipp(tag + " EndSession()");
      in_session_ = false;
      if (r_.chance(0.6)) rest_probe(RestProbe::End, step, tag, ipp_);
    } else if (k < 890) {  // the client drops, mid-move more often than not
      if (r_.chance(0.7)) {
        send_ipp(ctag() + " " + goto_line());
        wait(r_.pick(1, 800));
      }
      const int client = ipp_;
      const int step = close_ipp();
      rest_probe(RestProbe::Drop, step, "", client);
      open_ipp();
    } else if (k < 900) {  // a second client: refused, the session goes on
      const int c = next_client_++;
      s_.entries.push_back({EntryKind::Connect, c, "ipp"});
      ++step_;
      s_.refused_clients.insert(c);
    } else if (k < 915) {
      burst();
    } else if (k < 925) {
      fill_queue();
    } else if (k < 930) {
      frames_and_tools();
    } else if (k < 940) {
      static const char* more[] = {"GetDMEVersion()", "IsHomed()", "GetMachineClass()", "EnumTools()", "GetErrorInfo(2500)",
                                   "OnPtMeasReport(X(), Y(), Z(), IJK(), ER(), Q())", "OnPtMeasReport(Z(), X())",
                                   "EnumProp(Tool.PtMeasPar())", "StartSession()"};
      send_ipp(ctag() + " " + more[r_.pick(0, 8)]);
    } else {
      send_ipp(ctag() + " " + goto_line());
      for (int i = r_.pick(1, 3); i > 0; --i) join(ipp_, ctag() + " " + (r_.chance(0.5) ? goto_line() : std::string("Get(Z())")));
    }
  }

  // Client 1, the jog panel. Whatever it moves it stops again within the action, so a rest
  // probe never sees the panel's own motion.
  void panel_action() {
    const int k = r_.pick(0, 99);
    if (k < 40) {
      send(1, "Status");
    } else if (k < 55) {
      send(1, "StopMv");
    } else if (k < 90) {
      const int how = r_.pick(0, 2);
      if (how == 0 && m_.referenced) {  // the soft limits keep a jog within the travel
        static const char* dirs[] = {"5 0 0", "-5 0 0", "0 5 0", "0 0 5", "0 0 -5"};
        send(1, std::string("StartMv ") + dirs[r_.pick(0, 4)]);
        wait(r_.pick(1, 600));
        send(1, r_.chance(0.7) ? "StartMv 0 0 0" : "StopMv");
        return;
      }
      const std::string target = num(r_.coord(m_.lo[0] + 100, m_.hi[0] - 100)) + " " + num(r_.coord(m_.lo[1] + 100, m_.hi[1] - 100)) + " " +
                                 num(r_.coord(m_.safe_z, std::max(m_.safe_z, m_.hi[2] - 100)));
      send(1, how == 1 ? "GoTo " + target : "MoveTo 7 X" + target.substr(0, target.find(' ')) + " F30");
      wait(r_.pick(1, 600));
      send(1, "StopMv");
    } else {  // the operator takes over to clear a fault, then hands the machine back
      send(1, "Take force");
      send(1, "Reset");
      send(1, "Release");
    }
  }

  void action() {
    const int k = r_.pick(0, 99);
    if (k < 30) {
      const int w = r_.pick(0, 9);
      wait(w < 4 ? r_.pick(1, 50) : w < 8 ? r_.pick(50, 1000) : r_.pick(1000, 4000));
    } else if (k < 40) {
      panel_action();
    } else if (ipp_ == 0) {
      open_ipp();
    } else {
      ipp_action();
    }
  }

  const Machine& m_;
  Random r_;
  Script s_;
  std::vector<RestProbe> probes_;
  int step_ = 0, ipp_ = 0, next_client_ = 2, cmd_ = 0, evt_ = 0;
  bool in_session_ = false;
  std::string daemon_;
  std::deque<std::string> recent_;
};

}  // namespace

Script make_script(const Machine& m, std::uint64_t seed, int actions) { return Generator(m, seed).make(actions); }

}  // namespace imess::golden::ippdme_properties
