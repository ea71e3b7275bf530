// Fuzz target: I++ DME client bytes -> LineFramer -> parse_framed, as the server's session
// reads them; every error is formatted, every request formatted and parsed back; the
// property paths of GetProp / SetProp / EnumProp go through a ToolBox as the server's do, and a
// SetCsyTransformation through a CsyChain (the origin and axes must stay finite), an
// OnScanReport's items through the scan data line and back. The first byte
// chooses the read size, so lines are split across reads at every place.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include <cmath>

#include "imess/ippdme/csy.hpp"
#include "imess/ippdme/format.hpp"
#include "imess/ippdme/line_framer.hpp"
#include "imess/ippdme/parser.hpp"
#include "imess/ippdme/tools.hpp"

using namespace imess::ippdme;

namespace {
// Tight enough that a fuzzer reaches the cap; the spec's 65 536 is tested in test_ippdme.
constexpr std::size_t kFuzzLineLength = 512;

void check_line(std::string_view line) {  // one output line: bytes 32..126, then CR LF
  if (line.size() < 2 || line.substr(line.size() - 2) != "\r\n") std::abort();
  for (char c : line.substr(0, line.size() - 2))
    if (c < 32 || c > 126) std::abort();
}

ToolBox make_tools() {
  ToolSpec t;
  t.name = "RefTool";
  t.radius = 2;
  for (auto& r : t.params) r = {0.5, 100, 10};
  return ToolBox({t});
}

// A property answer is a value or a declared error, never both or neither; Act stays in range.
void check_property(const PropertyResult& r, ToolBox& tools) {
  if (r.value && r.error) std::abort();
  if (r.error && !find_error(number_of(*r.error))) std::abort();
  if (r.value) check_line(format_data(kServerTag, std::vector<Value>{*r.value}));
  for (int p = 0; p < kParamCount; ++p)
    if (tools.active() && (tools.act(static_cast<Param>(p)) < 0.5 || tools.act(static_cast<Param>(p)) > 100)) std::abort();
}

void exercise_properties(const Command& cmd, ToolBox& tools) {
  ErrorCode err{};
  if (const auto* g = std::get_if<GetProp>(&cmd))
    for (const auto& path : g->paths) check_property(tools.get(path), tools);
  if (const auto* s = std::get_if<SetProp>(&cmd))
    for (const auto& set : s->settings) check_property(tools.set(set.path, set.value), tools);
  if (const auto* e = std::get_if<EnumProp>(&cmd))
    if (auto entries = tools.enumerate(e->path, false, err))
      for (const auto& [name, kind] : *entries) check_line(format_data(kServerTag, std::vector<Value>{Value::of_string(name), Value::of_string(kind)}));
  if (const auto* c = std::get_if<ChangeTool>(&cmd)) tools.change(c->name);
  if (const auto* f = std::get_if<FindTool>(&cmd)) tools.find_tool(f->name);
}

// A transformation the parser accepts maps the origin and the axes to finite machine
// coordinates, as messd's PartCsy frame needs (issue 26: 1.7e308 offsets gave inf).
void exercise_csy(const Command& cmd, CsyChain& chain) {
  const auto* t = std::get_if<SetCsyTransformation>(&cmd);
  if (!t) return;
  chain.set(t->csy, t->transform);
  chain.select(CoordSystem::PartCsy);
  for (const Point3& p : {Point3{0, 0, 0}, Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}})
    for (double v : chain.to_machine(p))
      if (!std::isfinite(v)) std::abort();
}
// A report list the parser accepts gives scan data lines that keep the line rules and read back
// to as many points.
void exercise_scan_report(const Command& cmd) {
  const auto* r = std::get_if<OnScanReport>(&cmd);
  if (!r) return;
  ScanPoint points[2];
  points[1].xyz = {-1e300, 123.45678, 0};
  points[1].q = 1e9;
  const std::string line = format_scan_data(kServerTag, r->items, points);
  check_line(line);
  const auto back = read_scan_data(std::string_view(line).substr(8, line.size() - 10), r->items);
  if (!back || back->size() != 2) std::abort();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t chunk = 1 + data[0] % 16;
  std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  LineFramer framer(kFuzzLineLength);
  TagTracker open;
  ToolBox tools = make_tools();
  CsyChain chain;
  for (std::size_t at = 0; at < bytes.size(); at += chunk) {
    framer.feed(bytes.substr(at, chunk), [&](const FramedLine& line) {
      if (line.text.size() > kFuzzLineLength) std::abort();
      LineResult r = parse_framed(line);
      if (auto* e = std::get_if<LineError>(&r)) {
        if (!find_error(number_of(e->code))) std::abort();
        check_line(format_error(*e, open));
        check_line(format_error(*e, open, CauseStyle::Quoted));
        return;
      }
      const auto& req = std::get<Request>(r);
      if (!open.try_open(req.tag)) open.close(req.tag);  // some reused, some not
      // What the library writes, it reads back to the same command.
      const std::string again = format_command(req.tag, req.command);
      check_line(again);
      LineResult back = parse_line(std::string_view(again).substr(0, again.size() - 2));
      auto* same = std::get_if<Request>(&back);
      if (!same || !(same->command == req.command) || !(same->tag == req.tag)) std::abort();
      exercise_properties(req.command, tools);
      exercise_csy(req.command, chain);
      exercise_scan_report(req.command);
    });
    if (framer.pending() > kFuzzLineLength) std::abort();
  }
  return 0;
}
