// The rings between the io thread and the motion loop keep their storage inside the object;
// constructing the core writes every slot once, so all of it is resident from the start
// (before, pages became resident one by one as a ring first went round: a slow RSS creep of
// messd and page faults in the motion cycle). Checked with mincore() on fresh anonymous pages.
#include <sys/mman.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <cstdint>
#include <new>
#include <random>
#include <vector>

#include "core_rig.hpp"
#include "imess/core/queues.hpp"

namespace {

// Fresh anonymous pages (none resident until written) for one T, and the object built in them.
template <typename T>
class FreshPages {
 public:
  FreshPages() {
    void* p = ::mmap(nullptr, bytes(), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    REQUIRE(p != MAP_FAILED);
    base_ = p;
  }
  ~FreshPages() {
    if (object_) object_->~T();
    ::munmap(base_, bytes());
  }
  FreshPages(const FreshPages&) = delete;
  FreshPages& operator=(const FreshPages&) = delete;

  template <typename... Args>
  T& build(Args&&... args) {
    object_ = new (base_) T(std::forward<Args>(args)...);
    return *object_;
  }
  // Pages of [begin, begin + size) not resident; the range is inside the mapping.
  std::size_t missing_pages(const void* begin, std::size_t size) const {
    const std::size_t page = page_size();
    const auto first = reinterpret_cast<std::uintptr_t>(begin) / page * page;
    const auto end = reinterpret_cast<std::uintptr_t>(begin) + size;
    const std::size_t n = (end - first + page - 1) / page;
    std::vector<unsigned char> in(n);
    REQUIRE(::mincore(reinterpret_cast<void*>(first), n * page, in.data()) == 0);
    std::size_t missing = 0;
    for (unsigned char c : in) missing += (c & 1) ? 0 : 1;
    return missing;
  }
  std::size_t missing_pages() const { return missing_pages(base_, sizeof(T)); }

 private:
  static std::size_t page_size() { return static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)); }
  static std::size_t bytes() { return (sizeof(T) + page_size() - 1) / page_size() * page_size(); }
  void* base_ = nullptr;
  T* object_ = nullptr;
};

}  // namespace

TEST_CASE("prefault_ring makes a ring's storage resident and leaves it empty and first-in first-out") {
  using Ring = imess::core::EventQueue;
  FreshPages<Ring> pages;
  Ring& ring = pages.build();
  const std::size_t capacity = ring.write_available();
  CHECK(pages.missing_pages() > 100);  // built but not yet written: the slots are not resident
  imess::core::prefault_ring(ring);
  CHECK(pages.missing_pages() == 0);
  CHECK(ring.read_available() == 0);
  CHECK(ring.write_available() == capacity);
  // Still a FIFO of full capacity, across the wrap-around, for random batch sizes.
  std::mt19937 rng(7);
  std::uint32_t next_in = 0, next_out = 0;
  for (int round = 0; round < 20; ++round) {
    const std::size_t n = std::uniform_int_distribution<std::size_t>(1, capacity)(rng);
    for (std::size_t i = 0; i < n; ++i) {
      imess::core::Event e;
      e.seq = next_in++;
      REQUIRE(ring.push(e));
    }
    if (n == capacity) CHECK_FALSE(ring.push(imess::core::Event{}));
    imess::core::Event e;
    while (ring.pop(e)) CHECK(e.seq == next_out++);
  }
  CHECK(next_out == next_in);
}

TEST_CASE("a constructed motion core is resident whole: its rings take no page on first use") {
  imess::test::CoreRig rig;  // the simulated machine; the core under test is a second one on it
  FreshPages<imess::core::MotionCore> pages;
  auto& core = pages.build(rig.backend(), imess::test::default_options().core);
  CHECK(pages.missing_pages(&core.events(), sizeof(imess::core::EventQueue)) == 0);
  CHECK(pages.missing_pages() == 0);
  CHECK(core.events().read_available() == 0);
}
