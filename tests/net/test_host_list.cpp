// CIDR lists: which peers the control rules admit, IPv4 and IPv6, mapped addresses, errors.
#include <catch2/catch.hpp>

#include "imess/net/host_list.hpp"

using namespace imess::net;
using boost::asio::ip::make_address;

TEST_CASE("Cidr: a prefix admits exactly its block") {
  std::string error;
  auto c = Cidr::parse("192.168.1.0/24", error);
  REQUIRE(c);
  CHECK(c->contains(make_address("192.168.1.0")));
  CHECK(c->contains(make_address("192.168.1.255")));
  CHECK_FALSE(c->contains(make_address("192.168.2.1")));
  CHECK_FALSE(c->contains(make_address("192.168.0.255")));
  CHECK_FALSE(c->contains(make_address("::1")));  // another family never matches
}

TEST_CASE("Cidr: odd prefix lengths, host bits cleared, a bare address is one host") {
  std::string error;
  auto c = Cidr::parse("10.1.2.3/13", error);  // 10.0.0.0 - 10.7.255.255
  REQUIRE(c);
  CHECK(c->to_string() == "10.0.0.0/13");
  CHECK(c->contains(make_address("10.7.255.255")));
  CHECK_FALSE(c->contains(make_address("10.8.0.0")));
  auto one = Cidr::parse("127.0.0.2", error);
  REQUIRE(one);
  CHECK(one->prefix == 32);
  CHECK(one->contains(make_address("127.0.0.2")));
  CHECK_FALSE(one->contains(make_address("127.0.0.1")));
  auto all = Cidr::parse("0.0.0.0/0", error);
  REQUIRE(all);
  CHECK(all->contains(make_address("203.0.113.9")));
}

TEST_CASE("Cidr: IPv6 blocks, and IPv4-mapped peers match as IPv4") {
  std::string error;
  auto lo = Cidr::parse("::1/128", error);
  REQUIRE(lo);
  CHECK(lo->contains(make_address("::1")));
  CHECK_FALSE(lo->contains(make_address("::2")));
  auto site = Cidr::parse("fd00:1234::/32", error);
  REQUIRE(site);
  CHECK(site->contains(make_address("fd00:1234:ffff::7")));
  CHECK_FALSE(site->contains(make_address("fd00:1235::7")));
  auto loop4 = Cidr::parse("127.0.0.0/8", error);
  REQUIRE(loop4);
  CHECK(loop4->contains(make_address("::ffff:127.0.0.5")));  // a dual-stack listener's view of 127.0.0.5
  CHECK_FALSE(loop4->contains(make_address("::ffff:10.0.0.5")));
}

TEST_CASE("Cidr: a bad entry says what is accepted") {
  std::string error;
  CHECK_FALSE(Cidr::parse("localhost", error));
  CHECK(error.find("'localhost' is not an IPv4 or IPv6 address") != std::string::npos);
  CHECK(error.find("\"127.0.0.0/8\"") != std::string::npos);
  CHECK_FALSE(Cidr::parse("10.0.0.0/33", error));
  CHECK(error.find("0 to 32") != std::string::npos);
  CHECK_FALSE(Cidr::parse("::/129", error));
  CHECK(error.find("0 to 128") != std::string::npos);
  CHECK_FALSE(Cidr::parse("10.0.0.0/", error));
  CHECK_FALSE(Cidr::parse("10.0.0.0/8x", error));
  CHECK_THROWS_WITH(HostList::parse({"127.0.0.0/8", "nonsense/8"}), Catch::Contains("'nonsense/8'"));
}

TEST_CASE("HostList: defaults are loopback for control and everything for observing") {
  auto lo = loopback_hosts();
  CHECK(lo.contains(make_address("127.0.0.1")));
  CHECK(lo.contains(make_address("127.255.0.9")));
  CHECK(lo.contains(make_address("::1")));
  CHECK_FALSE(lo.contains(make_address("192.168.1.10")));
  CHECK_FALSE(lo.contains(make_address("2001:db8::1")));
  auto any = any_host();
  CHECK(any.contains(make_address("192.168.1.10")));
  CHECK(any.contains(make_address("2001:db8::1")));
  CHECK_FALSE(HostList{}.contains(make_address("127.0.0.1")));  // an empty list admits nobody
  CHECK(lo.to_string() == "127.0.0.0/8, ::1/128");
}
