// Recursive-descent reader and writer of I++ DME values. Depth and line length are bounded,
// so no input can exhaust the stack; the only allocations are the tree itself.
#include "imess/ippdme/syntax.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "imess/protocol/numbers.hpp"

namespace imess::ippdme {
namespace {

bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

class Reader {
 public:
  explicit Reader(std::string_view text) : s_(text) {}

  CallResult top() {
    CallResult r;
    Value v;
    if (!is_letter(peek()) || !read_call_or_word(v, 1) || v.kind != ValueKind::Call) {
      r.error = error_ ? *error_ : SyntaxError{ErrorCode::ProtocolError, pos_};
      return r;
    }
    if (pos_ != s_.size()) {  // nothing may follow the closing parenthesis, not even a space
      r.error = SyntaxError{ErrorCode::ProtocolError, pos_};
      return r;
    }
    r.call = std::move(v);
    return r;
  }

 private:
  char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }
  void spaces() {
    while (peek() == ' ') ++pos_;
  }
  bool fail(ErrorCode code = ErrorCode::ProtocolError) {
    if (!error_) error_ = SyntaxError{code, pos_};
    return false;
  }

  bool read_name(std::string& out) {
    const std::size_t start = pos_;
    while (true) {
      if (!is_letter(peek())) return fail();  // every dotted part starts with a letter
      while (is_letter(peek()) || is_digit(peek())) ++pos_;
      if (peek() != '.') break;
      ++pos_;
    }
    out.assign(s_.substr(start, pos_ - start));
    return true;
  }

  // A name, then either a call (optional spaces before its `(`) or a bare word / event tag.
  bool read_call_or_word(Value& v, std::size_t depth) {
    if (!read_name(v.text)) return false;
    const std::size_t after_name = pos_;
    spaces();
    if (peek() != '(') {
      pos_ = after_name;  // the spaces belong to what follows (a comma or a parenthesis)
      const bool tag = v.text.size() == 5 && v.text[0] == 'E' && is_digit(v.text[1]) && is_digit(v.text[2]) &&
                       is_digit(v.text[3]) && is_digit(v.text[4]);
      v.kind = tag ? ValueKind::EventTag : ValueKind::Word;
      return true;
    }
    if (depth > kMaxNesting) return fail();
    v.kind = ValueKind::Call;
    ++pos_;
    spaces();
    if (peek() == ')') {
      ++pos_;
      return true;
    }
    while (true) {
      Value arg;
      if (!read_value(arg, depth + 1)) return false;
      v.args.push_back(std::move(arg));
      spaces();
      if (peek() == ',') {
        ++pos_;
        spaces();
        continue;
      }
      if (peek() == ')') {
        ++pos_;
        return true;
      }
      // Another value where a comma or `)` belongs (`X(1 0)`): the call's arguments are
      // wrong (0502); the line ending inside the call is the line's fault (0008).
      return fail(peek() == '\0' ? ErrorCode::ProtocolError : ErrorCode::IncorrectArguments);
    }
  }

  bool read_value(Value& v, std::size_t depth) {
    const char c = peek();
    if (c == '"') {
      const std::size_t close = s_.find('"', pos_ + 1);
      if (close == std::string_view::npos) return fail();
      v.kind = ValueKind::String;
      v.text.assign(s_.substr(pos_ + 1, close - pos_ - 1));
      pos_ = close + 1;
      return true;
    }
    if (is_letter(c)) return read_call_or_word(v, depth);
    if (is_digit(c) || c == '+' || c == '-' || c == '.') {
      const std::size_t start = pos_;
      while (is_digit(peek()) || peek() == '+' || peek() == '-' || peek() == '.' || peek() == 'e' || peek() == 'E')
        ++pos_;
      const std::string_view token = s_.substr(start, pos_ - start);
      v.kind = ValueKind::Number;
      v.text.assign(token);
      if (!parse_number_shape(token)) {
        pos_ = start;
        return fail();
      }
      auto n = imess::protocol::parse_number(token);
      if (!n) {
        pos_ = start;
        return fail(ErrorCode::IncorrectArguments);  // well formed, but beyond a double
      }
      v.number = *n;
      return true;
    }
    // A comma or `)` where a value belongs (`X(1,)`, `X(,1)`): a missing argument (0502).
    return fail(c == ',' || c == ')' ? ErrorCode::IncorrectArguments : ErrorCode::ProtocolError);
  }

 public:
  // [+-] (digits [. [digits]] | . digits) [(e|E) [+-] 1-3 digits], at most 16 mantissa digits.
  static bool parse_number_shape(std::string_view t) {
    std::size_t i = 0, digits = 0;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    std::size_t before = 0, after = 0;
    while (i < t.size() && is_digit(t[i])) ++i, ++before;
    if (i < t.size() && t[i] == '.') {
      ++i;
      while (i < t.size() && is_digit(t[i])) ++i, ++after;
    }
    if (before + after == 0) return false;
    digits = before + after;
    if (digits > kMaxNumberDigits) return false;
    if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
      ++i;
      if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
      std::size_t exp = 0;
      while (i < t.size() && is_digit(t[i])) ++i, ++exp;
      if (exp < 1 || exp > 3) return false;
    }
    return i == t.size();
  }

 private:
  std::string_view s_;
  std::size_t pos_ = 0;
  std::optional<SyntaxError> error_;
};

std::string sanitized_string(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c == '"' || c < 32 || c > 126) c = '\'';
  return out;
}

}  // namespace

CallResult parse_call(std::string_view text) { return Reader(text).top(); }

std::optional<double> parse_number_token(std::string_view token) {
  if (!Reader::parse_number_shape(token)) return std::nullopt;
  return imess::protocol::parse_number(token);
}

bool is_name(std::string_view s) {
  if (s.empty()) return false;
  bool part_start = true;
  for (char c : s) {
    if (c == '.') {
      if (part_start) return false;
      part_start = true;
      continue;
    }
    if (part_start && !is_letter(c)) return false;
    if (!is_letter(c) && !is_digit(c)) return false;
    part_start = false;
  }
  return !part_start;
}

std::string format_number(double v) {
  if (!std::isfinite(v) || v == 0) return "0";
  auto mantissa_digits = [](std::string_view text) {
    std::size_t n = 0;
    for (char c : text) {
      if (c == 'e') break;
      if (is_digit(c)) ++n;
    }
    return n;
  };
  char buf[64];
  // Shortest round-trip text, plain or scientific (0.001234567890123456 has 19 digits with its
  // leading zeros, 1.234567890123456e-03 has 16); rounded to 15 significant digits if neither fits.
  for (auto format : {std::chars_format::general, std::chars_format::scientific}) {
    auto r = format == std::chars_format::general ? std::to_chars(buf, buf + sizeof buf, v)
                                                  : std::to_chars(buf, buf + sizeof buf, v, format);
    if (r.ec != std::errc{}) continue;
    std::string_view text(buf, static_cast<std::size_t>(r.ptr - buf));
    if (mantissa_digits(text) <= kMaxNumberDigits) return std::string(text);
  }
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 15);
  return std::string(buf, static_cast<std::size_t>(r.ptr - buf));
}

std::string format_fixed(double v, int decimals) {
  if (!std::isfinite(v)) v = 0;
  std::string out;
  imess::protocol::append_fixed(out, v, decimals);
  // The grammar holds at most 16 digits: a value too large for these decimals is written
  // whole in its shortest form instead (never cut short).
  const auto digits = std::count_if(out.begin(), out.end(), [](char c) { return is_digit(c); });
  if (digits > static_cast<std::ptrdiff_t>(kMaxNumberDigits)) return format_number(v);
  return out;
}

Value Value::of_number(double v) {
  Value out;
  out.kind = ValueKind::Number;
  out.text = format_number(v);
  out.number = std::isfinite(v) ? v : 0;
  if (out.number == 0) out.number = 0;  // no negative zero
  return out;
}

Value Value::of_fixed(double v, int decimals) {
  Value out;
  out.kind = ValueKind::Number;
  out.text = format_fixed(v, decimals);
  out.number = std::isfinite(v) ? v : 0;
  return out;
}

Value Value::of_integer(long long v) {
  Value out;
  out.kind = ValueKind::Number;
  out.text = std::to_string(v);
  out.number = static_cast<double>(v);
  return out;
}

Value Value::of_string(std::string_view s) {
  Value out;
  out.kind = ValueKind::String;
  out.text = sanitized_string(s);
  return out;
}

Value Value::of_word(std::string_view w) {
  Value out;
  out.kind = ValueKind::Word;
  out.text.assign(w);
  return out;
}

Value Value::call(std::string_view name, std::vector<Value> args) {
  Value out;
  out.kind = ValueKind::Call;
  out.text.assign(name);
  out.args = std::move(args);
  return out;
}

void append_value(std::string& out, const Value& v) {
  switch (v.kind) {
    case ValueKind::Number:
      out += v.text.empty() ? format_number(v.number) : v.text;
      return;
    case ValueKind::String:
      out += '"';
      out += sanitized_string(v.text);
      out += '"';
      return;
    case ValueKind::Word:
    case ValueKind::EventTag:
      out += v.text;
      return;
    case ValueKind::Call:
      out += v.text;
      out += '(';
      for (std::size_t i = 0; i < v.args.size(); ++i) {
        if (i) out += ", ";
        append_value(out, v.args[i]);
      }
      out += ')';
      return;
  }
}

std::string format_value(const Value& v) {
  std::string out;
  append_value(out, v);
  return out;
}

std::string format_values(const std::vector<Value>& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out += ", ";
    append_value(out, values[i]);
  }
  return out;
}

}  // namespace imess::ippdme
