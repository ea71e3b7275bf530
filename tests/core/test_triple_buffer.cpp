// TripleBuffer: the reader always sees a whole, newest value; concurrently never torn.
#include <catch2/catch.hpp>

#include <atomic>
#include <thread>

#include "imess/core/triple_buffer.hpp"

using imess::core::TripleBuffer;

struct Wide {
  long a = 0, b = 0, c = 0, d = 0;
};

TEST_CASE("the reader gets the newest published value") {
  TripleBuffer<int> tb;
  tb.back() = 1;
  tb.publish();
  tb.back() = 2;
  tb.publish();
  CHECK(tb.read() == 2);
  CHECK(tb.read() == 2);
  tb.back() = 3;
  tb.publish();
  CHECK(tb.read() == 3);
}

TEST_CASE("values are never torn under concurrent writing") {
  TripleBuffer<Wide> tb;
  std::atomic<bool> stop{false};
  std::thread writer([&] {
    for (long i = 1; !stop.load(); ++i) {
      auto& w = tb.back();
      w = {i, i, i, i};
      tb.publish();
    }
  });
  long last = 0;
  for (int i = 0; i < 200000; ++i) {
    const Wide& w = tb.read();
    REQUIRE(w.a == w.b);
    REQUIRE(w.b == w.c);
    REQUIRE(w.c == w.d);
    REQUIRE(w.a >= last);  // never goes back in time
    last = w.a;
  }
  stop = true;
  writer.join();
}
