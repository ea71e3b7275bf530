// CIDR parsing and matching for the control rules.
#include "imess/net/host_list.hpp"

#include <array>
#include <charconv>
#include <stdexcept>

namespace imess::net {

namespace ip = boost::asio::ip;

namespace {

// IPv4-mapped IPv6 peers (a dual-stack listener on "::") are matched as the IPv4 address.
ip::address plain(const ip::address& a) {
  if (a.is_v6() && a.to_v6().is_v4_mapped()) return ip::make_address_v4(ip::v4_mapped, a.to_v6());
  return a;
}

template <std::size_t N>
std::array<unsigned char, N> masked(std::array<unsigned char, N> bytes, unsigned prefix) {
  for (std::size_t i = 0; i < N; ++i) {
    unsigned keep = prefix >= 8 * (i + 1) ? 8 : prefix > 8 * i ? prefix - 8 * i : 0;
    bytes[i] &= static_cast<unsigned char>(keep == 0 ? 0 : 0xFF << (8 - keep));
  }
  return bytes;
}

ip::address masked(const ip::address& a, unsigned prefix) {
  if (a.is_v4()) return ip::address_v4(masked(a.to_v4().to_bytes(), prefix));
  return ip::address_v6(masked(a.to_v6().to_bytes(), prefix));
}

}  // namespace

std::optional<Cidr> Cidr::parse(std::string_view text, std::string& error) {
  auto bad = [&](const std::string& why) {
    error = "'" + std::string(text) + "' " + why +
            "; accepted: an address with an optional prefix length, e.g. \"127.0.0.0/8\", \"192.168.1.20\", \"::1/128\"";
    return std::nullopt;
  };
  auto slash = text.find('/');
  boost::system::error_code ec;
  auto address = ip::make_address(std::string(text.substr(0, slash)), ec);
  if (ec) return bad("is not an IPv4 or IPv6 address");
  address = plain(address);
  const unsigned bits = address.is_v4() ? 32 : 128;
  unsigned prefix = bits;
  if (slash != std::string_view::npos) {
    auto digits = text.substr(slash + 1);
    auto [end, err] = std::from_chars(digits.data(), digits.data() + digits.size(), prefix);
    if (digits.empty() || err != std::errc() || end != digits.data() + digits.size() || prefix > bits)
      return bad("has a bad prefix length (0 to " + std::to_string(bits) + ")");
  }
  return Cidr{masked(address, prefix), prefix};
}

bool Cidr::contains(const ip::address& a) const {
  auto p = plain(a);
  if (p.is_v4() != network.is_v4()) return false;
  return masked(p, prefix) == network;
}

std::string Cidr::to_string() const { return network.to_string() + "/" + std::to_string(prefix); }

HostList HostList::parse(const std::vector<std::string>& texts) {
  std::vector<Cidr> blocks;
  for (const auto& t : texts) {
    std::string error;
    auto c = Cidr::parse(t, error);
    if (!c) throw std::invalid_argument(error);
    blocks.push_back(*c);
  }
  return HostList(std::move(blocks));
}

bool HostList::contains(const ip::address& a) const {
  for (const auto& b : blocks_)
    if (b.contains(a)) return true;
  return false;
}

std::string HostList::to_string() const {
  std::string s;
  for (const auto& b : blocks_) s += (s.empty() ? "" : ", ") + b.to_string();
  return s.empty() ? "none" : s;
}

HostList loopback_hosts() { return HostList::parse({"127.0.0.0/8", "::1/128"}); }
HostList any_host() { return HostList::parse({"0.0.0.0/0", "::/0"}); }

}  // namespace imess::net
