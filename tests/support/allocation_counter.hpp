// Counts heap allocations for the real-time tests: replaces the global operator new and
// delete, and proves the replacement counts. Include in exactly one source file of a test
// executable (after catch.hpp).
#pragma once
#include <atomic>
#include <cstdlib>
#include <new>
#include <type_traits>

namespace imess::test {
inline std::atomic<long> g_allocations{0};
inline std::atomic<bool> g_counting{false};

// Allocations during `cycles` motion cycles of a rig (CoreRig, MotionRig): the core is
// stepped directly and its events popped and dropped — collecting them would allocate.
template <class Rig>
long allocations_over_cycles(Rig& rig, int cycles) {
  auto& core = rig.core();
  g_allocations = 0;
  g_counting = true;
  for (int i = 0; i < cycles; ++i) {
    rig.clock().advance(Rig::kPeriod);
    core.cycle(rig.clock().now());
    typename std::remove_reference_t<decltype(core.events())>::value_type e;
    while (core.events().pop(e)) {}
  }
  g_counting = false;
  return g_allocations.load();
}
}  // namespace imess::test

void* operator new(std::size_t n) {
  if (imess::test::g_counting.load(std::memory_order_relaxed))
    imess::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

TEST_CASE("the allocation counter works") {
  imess::test::g_allocations = 0;
  imess::test::g_counting = true;
  auto* p = new int(3);
  imess::test::g_counting = false;
  delete p;
  REQUIRE(imess::test::g_allocations.load() == 1);
}
