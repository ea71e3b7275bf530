// HOST[:PORT] parsing: defaults, IPv6 brackets, and errors that say what is accepted.
#include <catch2/catch.hpp>

#include "imess/client/endpoint.hpp"
#include "imess/client/usage_error.hpp"

using imess::client::Endpoint;
using imess::client::parse_endpoint;
using imess::client::UsageError;

TEST_CASE("parse_endpoint: host alone takes port 1066") {
  CHECK(parse_endpoint("localhost") == Endpoint{"localhost", 1066});
  CHECK(parse_endpoint("192.168.0.5") == Endpoint{"192.168.0.5", 1066});
}

TEST_CASE("parse_endpoint: host and port") {
  CHECK(parse_endpoint("localhost:1067") == Endpoint{"localhost", 1067});
  CHECK(parse_endpoint("127.0.0.1:65535") == Endpoint{"127.0.0.1", 65535});
  CHECK(parse_endpoint(":2000") == Endpoint{"localhost", 2000});
}

TEST_CASE("parse_endpoint: IPv6 in brackets, and bare") {
  CHECK(parse_endpoint("[::1]:1066") == Endpoint{"::1", 1066});
  CHECK(parse_endpoint("[::1]") == Endpoint{"::1", 1066});
  CHECK(parse_endpoint("[fe80::1]:7") == Endpoint{"fe80::1", 7});
  CHECK(parse_endpoint("::1") == Endpoint{"::1", 1066});
}

TEST_CASE("parse_endpoint: what the text leaves out comes from the client's defaults (messipp: 127.0.0.1:1294)") {
  const Endpoint ipp{"127.0.0.1", 1294};
  CHECK(parse_endpoint("cmm", ipp) == Endpoint{"cmm", 1294});
  CHECK(parse_endpoint("cmm:1300", ipp) == Endpoint{"cmm", 1300});
  CHECK(parse_endpoint(":1300", ipp) == Endpoint{"127.0.0.1", 1300});
  CHECK(parse_endpoint("[::1]", ipp) == Endpoint{"::1", 1294});
  CHECK(parse_endpoint("::1", ipp) == Endpoint{"::1", 1294});
  CHECK_THROWS_WITH(parse_endpoint("cmm:x", ipp), Catch::Contains("localhost:1294") && !Catch::Contains("1066"));
  Endpoint e = ipp;
  bool seen = false;
  imess::client::take_host_argument("cmm", e, seen);
  CHECK(e == Endpoint{"cmm", 1294});
  CHECK(seen);
}

TEST_CASE("Endpoint::to_string brackets IPv6 literals") {
  CHECK(Endpoint{"localhost", 1066}.to_string() == "localhost:1066");
  CHECK(Endpoint{"::1", 1066}.to_string() == "[::1]:1066");
}

TEST_CASE("parse_endpoint: malformed text is rejected with what is accepted") {
  for (const char* bad : {"", "host:", "host:0", "host:65536", "host:12x", "host:-1", "[::1", "[]:1066",
                          "[::1]1066", "a b"}) {
    INFO(bad);
    CHECK_THROWS_AS(parse_endpoint(bad), UsageError);
  }
  CHECK_THROWS_WITH(parse_endpoint("host:99999"),
                    Catch::Contains("'host:99999'") && Catch::Contains("1..65535") &&
                        Catch::Contains("HOST[:PORT]"));
}
