// The observer fan-out: hooks in the order observers were added, each under its own guard (an
// observer that fails ends only itself), and a queued id's Done / Failed to the one that claims it.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "imess/net/observers.hpp"

using namespace imess;
using net::MotionObserver;

namespace {
struct Recorder : MotionObserver {
  Recorder(std::string n, std::vector<std::string>& into, std::uint32_t first = 0, std::uint32_t end = 0)
      : name(std::move(n)), log(into), from(first), to(end) {}
  bool owns_segment(std::uint32_t id) const override { return id >= from && id < to; }
  void homed() override { log.push_back(name + " homed"); }
  void key(const std::string& k) override {
    if (throws) throw std::runtime_error("broken");
    log.push_back(name + " key " + k);
  }
  bool listens_for_keys() const override { return keys; }
  bool guarded(std::string_view what, const std::function<void()>& f) override {
    if (!catches) return MotionObserver::guarded(what, f);
    try {
      f();
      return true;
    } catch (const std::exception&) {
      log.push_back(name + " ended in " + std::string(what));
      return false;
    }
  }
  std::string name;
  std::vector<std::string>& log;
  std::uint32_t from, to;
  bool throws = false, catches = false, keys = false;
};
}  // namespace

TEST_CASE("Observers: every hook reaches every observer in the order added") {
  std::vector<std::string> log;
  Recorder a("a", log), b("b", log);
  net::Observers obs;
  obs.add(a);
  obs.add(b);
  obs.each("Homed", [](MotionObserver& o) { o.homed(); });
  CHECK(log == std::vector<std::string>{"a homed", "b homed"});
}

TEST_CASE("Observers: a failing observer that guards itself ends only itself") {
  std::vector<std::string> log;
  Recorder a("a", log), b("b", log), c("c", log);
  b.throws = b.catches = true;
  net::Observers obs;
  obs.add(a);
  obs.add(b);
  obs.add(c);
  obs.each("KeyPress", [](MotionObserver& o) { o.key("F1"); });
  CHECK(log == std::vector<std::string>{"a key F1", "b ended in KeyPress", "c key F1"});
}

TEST_CASE("Observers: a queued id belongs to the first observer claiming it, else to the fallback") {
  std::vector<std::string> log;
  Recorder messd("messd", log, 0, 0xFFFFFFFFu), ipp("ipp", log, 0xF0000000u, 0xFFFFFF00u), program("program", log, 1, 100);
  net::Observers obs;
  obs.add(messd);
  obs.set_fallback(messd);
  obs.add(ipp);
  obs.add(program);
  CHECK(obs.owner_of(0xF0000001u) == &ipp);
  CHECK(obs.owner_of(7) == &program);
  CHECK(obs.owner_of(500) == &messd);  // the fallback claims all, but is asked last
  CHECK_FALSE(obs.any_listens_for_keys());
  ipp.keys = true;
  CHECK(obs.any_listens_for_keys());
}
