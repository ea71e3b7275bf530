// The figure runners of bench_net, one per subcommand (docs/performance.md, "Network figures").
// Each measures messd and its bench_echo reference in the same run and adds to the report.
#pragma once
#include "context.hpp"

namespace imess::bench {

void run_push(Context& ctx);    // push.forcept.N.*, push.probe.100.*, floor.broadcast.N.*, floor.stamped.100.*
void run_stream(Context& ctx);  // stream.*, floor.timer.*
void run_jog(Context& ctx);     // jog.*, with the Status round trip as reference
void run_rtt(Context& ctx);     // rtt.status.*, floor.echo.*
void run_memory(Context& ctx);  // memory.*
void run_load(Context& ctx);    // load.*: a load generator, no goals
void run_scan(Context& ctx);    // push.scan.100.*, floor.stamped1k.100.*: a scan's points at 1000/s

// Adds p50 and p99 figures of a latency sample set (ms), with the reference's when given
// (reference_id names the reference figure stem: "floor.broadcast.100" -> .p50/.p99), and
// its raw samples as the distribution `id`.
struct LatencySet {
  std::string id;     // e.g. "push.forcept.100"
  std::string label;  // printed, e.g. "ForcePt -> MeasPt at all 100 clients"
  std::string what;   // the whole description
  std::vector<double> ms;
};
void add_latency(Report& r, const LatencySet& set, const LatencySet* reference, std::optional<Goal> p50_goal,
                 std::optional<Goal> p99_goal);

}  // namespace imess::bench
