// A measured point leaves the daemon: numbered and written to the journal first, then
// `Hit` and the 1996 `MeasPt` to every client. A client can never hold a hit the journal lacks.
#include "imess/net/hit_service.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include "imess/protocol/messages.hpp"

namespace imess::net {

void HitService::measured(const core::Event& e) {
  if (e.kind == core::EventKind::ScanPt) return scan_point(e);
  ++points_;
  core::Event point = e;  // the probe offset (a qualification's) moves every measured point
  point.p += hal::Vec3(probe_offset_[0], probe_offset_[1], probe_offset_[2]);
  const JournaledHit journaled = record(point);  // journal, then Hit, then the 1996 MeasPt
  observers_.each("Hit", [&](MotionObserver& o) { o.hit(point, journaled); });
  if (options_.log_motion)
    spdlog::info("point {}: {:.4f} {:.4f} {:.4f} {} dir {:.4f} {:.4f} {:.4f}", points_, point.p.x(), point.p.y(), point.p.z(),
                 e.compensated ? "compensated" : "as is (ForcePt)", e.dir.x(), e.dir.y(), e.dir.z());
  else
    spdlog::info("point {}: {:.3f} {:.3f} {:.3f}", points_, point.p.x(), point.p.y(), point.p.z());
  if (options_.beep && isatty(STDERR_FILENO)) {
    [[maybe_unused]] auto n = ::write(STDERR_FILENO, "\a", 1);
  }
}

void HitService::scan_point(const core::Event& e) {
  ++scan_points_;
  core::Event point = e;
  point.p += hal::Vec3(probe_offset_[0], probe_offset_[1], probe_offset_[2]);
  const JournaledHit journaled = record(point, true);
  observers_.each("Scan", [&](MotionObserver& o) { o.scanned(point, journaled); });
}

JournaledHit HitService::record(const core::Event& e, bool scan) {
  protocol::HitMsg hit{0, e.id, {e.p.x(), e.p.y(), e.p.z()}, {e.dir.x(), e.dir.y(), e.dir.z()}, e.radius,
                       hal::seconds(e.time), scan};
  std::string line;
  try {
    line = journal_.append(hit);
  } catch (const journal::JournalError& err) {
    // The point is still sent (losing it would be worse); only Replay cannot give it again.
    spdlog::error("{}; the hit is sent to the clients anyway, but Replay cannot give it again", err.what());
    line = protocol::format_hit(hit);
  }
  return {hit, std::move(line)};
}

}  // namespace imess::net
