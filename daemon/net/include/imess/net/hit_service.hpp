// HitService: a measured point leaves the daemon — moved by the probe offset, numbered and
// written to the journal first, then handed to every observer (MESSD's Hit / MeasPt / PartPt,
// the I++ DME session's report). A client can never hold a hit the journal lacks. Also what
// the journal gives back: Replay, the hits an alignment fits.
#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "imess/journal/journal.hpp"
#include "imess/net/observers.hpp"

namespace imess::net {

class HitService : public MotionObserver {
 public:
  struct Options {
    bool log_motion = false;
    bool beep = true;  // BEL on the console for every point (when it is a terminal)
  };
  HitService(journal::Journal& journal, Observers& observers, std::array<double, 3>& probe_offset, Options options)
      : journal_(journal), observers_(observers), probe_offset_(probe_offset), options_(options) {}

  void measured(const core::Event& e) override;  // the loop's MeasPt: journal, then every observer's hit()
  // A scan's point (the loop's ScanPt): journaled in the same sequence, then every observer's
  // scanned(). Not logged one by one (hundreds a second): scan_points() counts them.
  void scan_point(const core::Event& e);
  std::uint64_t scan_points() const noexcept { return scan_points_; }
  // ProbeOffX/Y/Z: added to every measured point (mm); Qualify and Set change it.
  std::array<double, 3>& probe_offset() noexcept { return probe_offset_; }
  // Replay <from>: the journaled lines as the reply (with its Ok or Err line).
  std::string replay(std::uint32_t client, std::uint64_t from) const;
  journal::Journal& journal() noexcept { return journal_; }

 private:
  JournaledHit record(const core::Event& e, bool scan = false);

  journal::Journal& journal_;
  Observers& observers_;
  std::array<double, 3>& probe_offset_;
  Options options_;
  std::uint64_t points_ = 0;
  std::uint64_t scan_points_ = 0;
};

}  // namespace imess::net
