// Property tests, seeded: random valid commands survive format -> frame -> parse unchanged;
// random byte mutations of valid lines always give a Request or a known error, never a throw.
#include <catch2/catch.hpp>

#include <algorithm>

#include <cmath>
#include <random>
#include <string>

#include "imess/ippdme/format.hpp"
#include "imess/ippdme/parser.hpp"
#include "imess/ippdme/syntax.hpp"

using namespace imess::ippdme;

namespace {
class Gen {
 public:
  explicit Gen(std::uint32_t seed) : rng_(seed) {}
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  bool coin() { return integer(0, 1) == 1; }
  // A decimal with up to 9 digits and 0..6 decimals, sometimes scaled by a power of ten.
  // (m / 10^d and m e k are the doubles nearest those decimals, so they print back in <= 9 digits.)
  double number() {
    double v = integer(-999999999, 999999999) / std::pow(10.0, integer(0, 6));
    if (integer(0, 9) == 0)
      v = *parse_number_token(std::to_string(integer(-999999, 999999)) + "e" + std::to_string(integer(-300, 300)));
    return v;
  }
  // A coordinate system's offset: within ±kMaxCsyOffset (1e6 mm), up to 9 digits.
  double offset() { return integer(-999999999, 999999999) / std::pow(10.0, integer(3, 6)); }
  std::optional<double> maybe() { return coin() ? std::optional<double>(number()) : std::nullopt; }
  std::string name_part() {
    static const char* letters = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
    std::string s(1, letters[integer(0, 51)]);
    for (int n = integer(0, 8); n > 0; --n) s += coin() ? letters[integer(0, 51)] : static_cast<char>('0' + integer(0, 9));
    return s;
  }
  std::string path(int min_parts) {
    std::string p = name_part();
    for (int n = integer(min_parts - 1, 3); n > 0; --n) p += "." + name_part();
    return p;
  }
  std::string text() {  // printable, no quote, not empty
    std::string s;
    for (int n = integer(1, 20); n > 0; --n) {
      char c = static_cast<char>(integer(32, 126));
      s += c == '"' ? '\'' : c;
    }
    return s;
  }
  std::vector<Item> items(bool report) {
    std::vector<Item> out;
    for (int n = integer(1, 8); n > 0; --n) {  // each item at most once (a repeated one is 0502)
      const auto item = static_cast<Item>(integer(0, report ? 9 : 6));
      if (std::find(out.begin(), out.end(), item) == out.end()) out.push_back(item);
    }
    return out;
  }
  Axes axes(bool tool_axes) {
    Axes a;
    do {
      a.x = maybe();
      a.y = maybe();
      a.z = maybe();
      if (tool_axes) {
        a.tool_a = maybe();
        a.tool_b = maybe();
        a.tool_c = maybe();
      }
    } while (!a.x && !a.y && !a.z && !a.tool_a && !a.tool_b && !a.tool_c);
    return a;
  }

  // Scan geometry: coordinates with 3 decimals, small whole directions (never without norm),
  // a direction orthogonal to another (their cross product: exact in doubles).
  double coord() { return integer(-500000, 500000) / 1000.0; }
  double positive() { return integer(1, 100000) / 1000.0; }
  double nonzero() { return coin() ? positive() : -positive(); }
  double step() { return coin() ? 0.0 : positive(); }  // 0: the server's density
  int count() { return integer(1, 5); }
  Point3 point() { return {coord(), coord(), coord()}; }
  Vector3 direction() {
    Vector3 v;
    do v = {static_cast<double>(integer(-5, 5)), static_cast<double>(integer(-5, 5)), static_cast<double>(integer(-5, 5))};
    while (v.i == 0 && v.j == 0 && v.k == 0);
    return v;
  }
  Vector3 across(const Vector3& n) {
    Vector3 r;
    do {
      const Vector3 d = direction();
      r = {n.j * d.k - n.k * d.j, n.k * d.i - n.i * d.k, n.i * d.j - n.j * d.i};
    } while (r.i == 0 && r.j == 0 && r.k == 0);
    return r;
  }
  // p + v as the double nearest its decimals (a sum's last bit would need 17 digits to write).
  std::optional<Vector3> plane(bool given) { return given ? std::optional<Vector3>(direction()) : std::nullopt; }
  static Point3 plus(const Point3& p, const Vector3& v) {
    auto at = [](double a, double b) { return std::round((a + b) * 1000) / 1000; };
    return {at(p[0], v.i), at(p[1], v.j), at(p[2], v.k)};
  }

  Command command(std::size_t index) {
    switch (index) {
      case command_index<StopDaemon>(): return StopDaemon{{TagKind::Event, static_cast<std::uint32_t>(integer(1, 9999))}};
      case command_index<GetErrorInfo>(): return GetErrorInfo{integer(0, 9999)};
      case command_index<GetProp>(): return GetProp{paths()};
      case command_index<GetPropE>(): return GetPropE{paths()};
      case command_index<SetProp>(): return SetProp{settings()};
      case command_index<SetPropE>(): return SetPropE{settings()};
      case command_index<EnumProp>(): return EnumProp{path(1)};
      case command_index<EnumAllProp>(): return EnumAllProp{path(1)};
      case command_index<OnPtMeasReport>(): return OnPtMeasReport{items(true)};
      case command_index<OnMoveReportE>():
        return OnMoveReportE{coin() ? std::optional<double>(integer(0, 10000) / 100.0) : std::nullopt,
                             coin() ? std::optional<double>(integer(0, 10000) / 100.0) : std::nullopt, items(false)};
      case command_index<Get>(): return Get{items(false)};
      case command_index<GoTo>(): return GoTo{axes(true)};
      case command_index<PtMeas>(): {
        Axes a = axes(false);
        std::optional<Vector3> ijk;
        if (coin()) {
          do ijk = Vector3{integer(-1000, 1000) / 1000.0, integer(-1000, 1000) / 1000.0, integer(-1000, 1000) / 1000.0};
          while (ijk->i == 0 && ijk->j == 0 && ijk->k == 0);
        }
        return PtMeas{a, ijk};
      }
      case command_index<ChangeTool>(): return ChangeTool{text()};
      case command_index<SetTool>(): return SetTool{text()};
      case command_index<FindTool>(): return FindTool{text()};
      case command_index<GetChangeToolAction>(): return GetChangeToolAction{text()};
      case command_index<SetCoordSystem>(): return SetCoordSystem{static_cast<CoordSystem>(integer(0, 3))};
      case command_index<SetCsyTransformation>():
        return SetCsyTransformation{static_cast<CsyTarget>(integer(0, 5)),
                                    {offset(), offset(), offset(), integer(0, 180000) / 1000.0, number(), number()}};
      case command_index<GetCsyTransformation>(): return GetCsyTransformation{static_cast<CsyTarget>(integer(0, 5))};
      case command_index<OnScanReport>(): return OnScanReport{items(true)};
      case command_index<ScanOnCircleHint>(): return ScanOnCircleHint{coin() ? 0 : positive(), positive()};
      case command_index<ScanOnLineHint>(): return ScanOnLineHint{positive(), coin() ? 0 : positive()};
      case command_index<ScanUnknownHint>(): return ScanUnknownHint{positive()};
      case command_index<ScanUnknownDensity>(): {
        ScanUnknownDensity d;
        do {
          if (coin()) d.dis = positive();
          if (coin()) d.angle = positive();
          if (coin()) d.angle_base_length = positive();
        } while (!d.dis && !d.angle && !d.angle_base_length);
        return d;
      }
      case command_index<ScanOnCircle>(): {
        const Point3 c = point();
        const Vector3 n = direction();
        return ScanOnCircle{c, plus(c, across(n)), n, nonzero(), static_cast<double>(integer(-360, 360)), nonzero()};
      }
      case command_index<ScanOnHelix>(): {
        const Point3 c = point();
        const Vector3 n = direction();
        return ScanOnHelix{c, plus(c, across(n)), n, nonzero(), coin() ? 0.0 : 180.0, nonzero(), coord()};
      }
      case command_index<ScanOnLine>(): {
        const Point3 a = point();
        const Vector3 n = direction();
        return ScanOnLine{a, plus(a, across(n)), n, positive()};
      }
      // A plane scan in its 1.4.3 form, or the 1.4.0 one (no plane normal: the direction point
      // off the start's surface direction; the sphere's without n: count 1).
      case command_index<ScanInPlaneEndIsSphere>(): {
        const Point3 a = point();
        const Vector3 n = direction();
        const bool v143 = coin();
        return ScanInPlaneEndIsSphere{a,        n,        plane(v143), plus(a, across(n)), step(), point(), positive(),
                                      v143 ? count() : 1, direction()};
      }
      case command_index<ScanInPlaneEndIsPlane>(): {
        const Point3 a = point();
        const Vector3 n = direction();
        return ScanInPlaneEndIsPlane{a, n, plane(coin()), plus(a, across(n)), step(), point(), direction(), count(), direction()};
      }
      case command_index<ScanInPlaneEndIsCyl>(): {
        const Point3 a = point();
        const Vector3 n = direction();
        return ScanInPlaneEndIsCyl{a,       n,          plane(coin()), plus(a, across(n)), step(), point(), direction(),
                                   positive(), count(), direction()};
      }
      case command_index<ScanInCylEndIsSphere>(): {
        const Point3 c = point();
        const Vector3 axis = direction();
        const Point3 a = plus(c, across(axis));
        return ScanInCylEndIsSphere{c, axis, a, direction(), plus(a, direction()), step(), point(), positive(), count(), direction()};
      }
      case command_index<ScanInCylEndIsPlane>(): {
        const Point3 c = point();
        const Vector3 axis = direction();
        const Point3 a = plus(c, across(axis));
        return ScanInCylEndIsPlane{c, axis, a, direction(), plus(a, direction()), step(), point(), direction(), count(), direction()};
      }
      default: return default_of(index);
    }
  }
  Tag tag_for(const Command& c) {
    if (declaration_of(c).queue == Queue::Fast) return {TagKind::Event, static_cast<std::uint32_t>(integer(1, 9999))};
    return {TagKind::Command, static_cast<std::uint32_t>(integer(1, 99999))};
  }

 private:
  std::vector<std::string> paths() {
    std::vector<std::string> out;
    for (int n = integer(1, 4); n > 0; --n) out.push_back(path(2));
    return out;
  }
  std::vector<PropertySetting> settings() {
    std::vector<PropertySetting> out;
    for (int n = integer(1, 4); n > 0; --n) out.push_back({path(2), number()});
    return out;
  }
  template <std::size_t I = 0>
  static Command default_of(std::size_t index) {  // the commands without fields
    if constexpr (I < std::variant_size_v<Command>) {
      if (index == I) return std::variant_alternative_t<I, Command>{};
      return default_of<I + 1>(index);
    } else {
      return StartSession{};
    }
  }
  std::mt19937 rng_;
};
}  // namespace

TEST_CASE("ippdme property: random valid commands format, frame and parse back to the same model") {
  for (std::uint32_t seed : {1u, 2u, 3u, 20261123u}) {
    Gen gen(seed);
    LineFramer framer;
    for (int n = 0; n < 3000; ++n) {
      const auto index = static_cast<std::size_t>(gen.integer(0, std::variant_size_v<Command> - 1));
      const Command cmd = gen.command(index);
      const Tag tag = gen.tag_for(cmd);
      const std::string line = format_command(tag, cmd);
      INFO("seed " << seed << ": " << line);
      int lines = 0;
      framer.feed(line, [&](const FramedLine& framed) {
        ++lines;
        auto r = parse_framed(framed);
        if (auto* e = std::get_if<LineError>(&r)) FAIL("error " << number_of(e->code));
        const auto& req = std::get<Request>(r);
        CHECK(req.tag == tag);
        CHECK(req.command == cmd);
        CHECK(format_command(req.tag, req.command) == line);
      });
      CHECK(lines == 1);
    }
  }
}

TEST_CASE("ippdme property: mutated lines give a request or a declared error, never a throw") {
  Gen gen(7);
  int errors = 0, requests = 0;
  for (int n = 0; n < 20000; ++n) {
    const Command cmd = gen.command(static_cast<std::size_t>(gen.integer(0, std::variant_size_v<Command> - 1)));
    std::string line = format_command(gen.tag_for(cmd), cmd);
    line.resize(line.size() - 2);
    for (int m = gen.integer(1, 4); m > 0; --m) {
      const auto at = static_cast<std::size_t>(gen.integer(0, static_cast<int>(line.size()) - 1));
      switch (gen.integer(0, 3)) {
        case 0: line[at] = static_cast<char>(gen.integer(0, 255)); break;
        case 1: line.erase(at, 1); break;
        case 2: line.insert(at, 1, " (),.\"E0-e"[gen.integer(0, 10)]); break;
        default: line.insert(at, line.substr(0, static_cast<std::size_t>(gen.integer(0, 20)))); break;
      }
      if (line.empty()) line = "x";
    }
    INFO(line);
    LineResult r = Request{kServerTag, StartSession{}};
    REQUIRE_NOTHROW(r = parse_line(line));
    if (auto* e = std::get_if<LineError>(&r)) {
      ++errors;
      CHECK(find_error(number_of(e->code)) != nullptr);
      CHECK(e->cause.size() <= 64);
      const std::string out = format_error(*e, TagTracker{});
      CHECK(out.find_first_of("\r\n") == out.size() - 2);
    } else {
      ++requests;
    }
  }
  CHECK(errors > 1000);
  CHECK(requests > 100);
}
