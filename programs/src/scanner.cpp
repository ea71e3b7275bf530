// Lines, plain decimal numbers and error text shared by the G-code, HPGL and MRM readers.
#include "scanner.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace imess::programs::detail {

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find('\n', start);
    std::string_view l = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    if (end == std::string_view::npos) {
      if (start < text.size()) lines.push_back(l);
      return lines;
    }
    lines.push_back(l);
    start = end + 1;
  }
}

bool scan_number(std::string_view s, std::size_t& i, double& out, bool skip_blanks) {
  std::size_t k = i;
  if (skip_blanks)
    while (k < s.size() && is_blank(s[k])) ++k;
  std::string buf;
  if (k < s.size() && (s[k] == '+' || s[k] == '-')) {
    if (s[k] == '-') buf += '-';
    ++k;
  }
  std::size_t digits = 0;
  while (k < s.size() && s[k] >= '0' && s[k] <= '9') buf += s[k++], ++digits;
  if (k < s.size() && s[k] == '.') {
    buf += s[k++];
    while (k < s.size() && s[k] >= '0' && s[k] <= '9') buf += s[k++], ++digits;
  }
  if (digits == 0) return false;
  if (buf.back() == '.') buf += '0';
  if (buf.front() == '.' || (buf.size() > 1 && buf[0] == '-' && buf[1] == '.')) buf.insert(buf[0] == '-' ? 1 : 0, "0");
  double v = 0;
  auto [end, ec] = std::from_chars(buf.data(), buf.data() + buf.size(), v);
  if (ec != std::errc{} || end != buf.data() + buf.size() || !std::isfinite(v) || std::fabs(v) > 1e12) return false;
  out = v;
  i = k;
  return true;
}

std::string char_text(std::string_view s, std::size_t i) {
  if (i >= s.size()) return "end of line";
  const unsigned char c = static_cast<unsigned char>(s[i]);
  if (c >= 0x21 && c < 0x7f) return std::string("'") + static_cast<char>(c) + "'";
  char buf[16];
  std::snprintf(buf, sizeof buf, "byte 0x%02X", c);
  return buf;
}

Translation fail(ErrorKind kind, int line, int column, std::string found, std::string accepted) {
  Translation t;
  t.ok = false;
  t.error = Error{kind, line, column, std::move(found), std::move(accepted)};
  return t;
}

void raise(ErrorKind kind, int line, int column, std::string found, std::string accepted) {
  throw Failure{Error{kind, line, column, std::move(found), std::move(accepted)}};
}

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6f", v);
  std::string s(buf);
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

}  // namespace imess::programs::detail
