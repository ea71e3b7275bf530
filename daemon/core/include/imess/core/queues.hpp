// The two rings between the network side and the motion loop. Boost.Lockfree's SPSC queue
// with compile-time capacity: wait-free push/pop, storage inside the object, no allocation.
#pragma once
#include <boost/lockfree/spsc_queue.hpp>

#include "imess/core/core_types.hpp"
#include "imess/planner/segment.hpp"

namespace imess::core {

inline constexpr std::size_t kCommandCapacity = 256;  // a full ring is an immediate Err QueueFull
inline constexpr std::size_t kEventCapacity = 4096;   // drained by the io thread as soon as the loop wakes it
inline constexpr int kCommandsPerCycle = 8;           // bounded work per motion cycle

// Planned segments, io thread -> loop. A full ring is not waited on: the io side keeps the
// rest in its planner and feeds them as Done events free room.
inline constexpr std::size_t kSegmentCapacity = 128;

// A segment with the stop ticket and the loop's drop count the io side knew when it sent it:
// a segment older than a stop or a drop is failed (Stopped), never run.
struct QueuedSegment {
  planner::PlannedSegment seg;
  std::uint64_t stop_ticket = 0;
  std::uint32_t drops = 0;
};
static_assert(std::is_trivially_copyable_v<QueuedSegment>);

using CommandQueue = boost::lockfree::spsc_queue<Command, boost::lockfree::capacity<kCommandCapacity>>;
using EventQueue = boost::lockfree::spsc_queue<Event, boost::lockfree::capacity<kEventCapacity>>;

}  // namespace imess::core

namespace imess::core {
using SegmentQueue = boost::lockfree::spsc_queue<QueuedSegment, boost::lockfree::capacity<kSegmentCapacity>>;

// Writes every slot of an empty ring once (a push and a pop per slot: the ring keeps one slot
// more than its capacity) and leaves it empty. The storage is inside the object and untouched
// until then, so without this its pages became resident one by one as the ring's write index
// first went round: at two events a second the event ring (736 KiB) took 34 minutes, a slow
// RSS creep, and every new page was a page fault in the motion cycle when mlockall is not in
// effect. Call before the loop and the io thread use the ring.
template <typename Ring>
void prefault_ring(Ring& ring) noexcept {
  typename Ring::value_type slot{};
  const std::size_t slots = ring.write_available() + 1;
  for (std::size_t i = 0; i < slots; ++i) {
    ring.push(slot);
    ring.pop(slot);
  }
}
}  // namespace imess::core
