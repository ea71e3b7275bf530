// HostList: which client addresses a rule admits — CIDR blocks such as "127.0.0.0/8" or
// "::1/128", IPv4 and IPv6. IPv4-mapped IPv6 peers (::ffff:a.b.c.d) match as IPv4.
#pragma once
#include <boost/asio/ip/address.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace imess::net {

struct Cidr {
  boost::asio::ip::address network;  // host bits cleared
  unsigned prefix = 0;               // 0..32 (IPv4), 0..128 (IPv6)

  // "a.b.c.d/n", "x::y/n", or an address alone (a single host). On failure: nullopt and a
  // message saying what is accepted.
  static std::optional<Cidr> parse(std::string_view text, std::string& error);
  bool contains(const boost::asio::ip::address& a) const;
  std::string to_string() const;
};

class HostList {
 public:
  HostList() = default;
  explicit HostList(std::vector<Cidr> blocks) : blocks_(std::move(blocks)) {}
  // Parses every entry; throws std::invalid_argument naming the first bad entry.
  static HostList parse(const std::vector<std::string>& texts);

  bool contains(const boost::asio::ip::address& a) const;
  bool empty() const { return blocks_.empty(); }
  std::string to_string() const;  // "127.0.0.0/8, ::1/128" (for the log)

 private:
  std::vector<Cidr> blocks_;
};

// Loopback only: 127.0.0.0/8 and ::1/128 (the default for control and forced take-over).
HostList loopback_hosts();
// Every address: 0.0.0.0/0 and ::/0 (the default for observing).
HostList any_host();

}  // namespace imess::net
