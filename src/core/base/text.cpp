#include "core/base/text.hpp"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace csl {
namespace {

bool digit(char c) { return c >= '0' && c <= '9'; }

// Digits from `i` on; returns how many.
std::size_t digits(std::string_view s, std::size_t& i) {
  const std::size_t from = i;
  while (i < s.size() && digit(s[i])) ++i;
  return i - from;
}

}  // namespace

bool is_decimal_syntax(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && s[i] == '-') ++i;
  const std::size_t whole = digits(s, i);
  std::size_t fraction = 0;
  if (i < s.size() && s[i] == '.') {
    ++i;
    fraction = digits(s, i);
  }
  if (whole == 0 && fraction == 0) return false;  // ".", "-", "" and "-.e5" are no numbers
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    if (digits(s, i) == 0) return false;
  }
  return i == s.size();
}

std::optional<double> parse_decimal(std::string_view text) {
  if (!is_decimal_syntax(text)) return std::nullopt;
  const std::string copy(text);  // strtod needs a terminated string
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(copy.c_str(), &end);
  // ERANGE with a finite result is an underflow: a number all the same, unlike an overflow.
  if (end != copy.c_str() + copy.size() || !std::isfinite(v) || (errno == ERANGE && std::fabs(v) > 1.0))
    return std::nullopt;
  return v;
}

std::optional<long long> parse_integer(std::string_view text) {
  std::size_t i = text.size() > 0 && text[0] == '-' ? 1 : 0;
  if (digits(text, i) == 0 || i != text.size()) return std::nullopt;
  const std::string copy(text);
  errno = 0;
  const long long v = std::strtoll(copy.c_str(), nullptr, 10);
  if (errno == ERANGE) return std::nullopt;
  return v;
}

std::string trim(std::string_view text) {
  constexpr std::string_view kSpace = " \t\n\v\f\r";  // isspace() in the C locale
  const auto b = text.find_first_not_of(kSpace);
  if (b == std::string_view::npos) return "";
  return std::string(text.substr(b, text.find_last_not_of(kSpace) - b + 1));
}

std::string printable(std::string_view text, std::size_t max) {
  std::string out;
  std::size_t cut = text.size();
  if (max < text.size()) {
    cut = max;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a character
  }
  for (std::size_t i = 0; i < cut; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    char escaped[8];
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7F) {
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else if (c == 0xC2 && i + 1 < cut && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
               static_cast<unsigned char>(text[i + 1]) <= 0x9F) {
      // U+0080..U+009F, the C1 controls (CSI among them) in UTF-8.
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned char>(text[i + 1]));
      out += escaped;
      ++i;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (cut < text.size()) out += "...";
  return out;
}

}  // namespace csl

namespace csl {

std::string significant(double v, int digits) {
  if (v == 0.0) return "0";  // (-0 too)
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

}  // namespace csl
