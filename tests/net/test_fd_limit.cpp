// Descriptor limit arithmetic: raise the soft limit when allowed, else cap max_clients.
#include <catch2/catch.hpp>

#include "fd_limit.hpp"

using namespace imess::app;

TEST_CASE("fd limit: enough already, nothing changes") {
  unsigned long soft = 0;
  auto r = plan_fd_limit(100, 1024, 4096, soft);
  CHECK(r.max_clients == 100);
  CHECK(r.message.empty());
  CHECK(soft == 1024);
}

TEST_CASE("fd limit: the soft limit is raised to what max_clients needs when the hard limit allows") {
  unsigned long soft = 0;
  auto r = plan_fd_limit(5000, 1024, 524288, soft);
  CHECK(soft == 5000 + kOtherDescriptors);
  CHECK(r.max_clients == 5000);
  CHECK_FALSE(r.lowered);
}

TEST_CASE("fd limit: above the hard limit, max_clients is lowered with one warning saying why") {
  unsigned long soft = 0;
  auto r = plan_fd_limit(10000, 1024, 2048, soft);
  CHECK(soft == 2048);
  CHECK(r.max_clients == 2048 - kOtherDescriptors);
  CHECK(r.lowered);
  CHECK(r.message.find("RLIMIT_NOFILE") != std::string::npos);
  CHECK(r.message.find("10000") != std::string::npos);
}
