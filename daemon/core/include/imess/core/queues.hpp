// The two rings between the network side and the motion loop. Boost.Lockfree's SPSC queue
// with compile-time capacity: wait-free push/pop, storage inside the object, no allocation.
#pragma once
#include <boost/lockfree/spsc_queue.hpp>

#include "imess/core/core_types.hpp"

namespace imess::core {

inline constexpr std::size_t kCommandCapacity = 256;  // a full ring is an immediate Err QueueFull
inline constexpr std::size_t kEventCapacity = 4096;   // drained by the io thread as soon as the loop wakes it
inline constexpr int kCommandsPerCycle = 8;           // bounded work per motion cycle

using CommandQueue = boost::lockfree::spsc_queue<Command, boost::lockfree::capacity<kCommandCapacity>>;
using EventQueue = boost::lockfree::spsc_queue<Event, boost::lockfree::capacity<kEventCapacity>>;

}  // namespace imess::core
