#include "core/base/params.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace csl {

std::string param_value_text(const ParamSpec& spec, double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char text[40];
  if (spec.integer || v == std::floor(v)) {
    std::snprintf(text, sizeof text, "%.0f", v);
  } else {
    // The shortest text that reads back as v ("0.02", not "0.0200000000000000004").
    for (int digits = 1; digits <= 17; ++digits) {
      std::snprintf(text, sizeof text, "%.*g", digits, v);
      if (std::strtod(text, nullptr) == v) break;
    }
  }
  return text;
}

std::string range_text(const ParamSpec& s) {
  const std::string lo = param_value_text(s, s.min), hi = param_value_text(s, s.max);
  const char* kind = s.integer ? "an integer" : "a number";
  if (std::isinf(s.max)) return std::string(kind) + (s.min_open ? " > " : " >= ") + lo;
  return std::string(kind) + " in " + (s.min_open ? "(" : "[") + lo + ", " + hi + "]";
}

std::string param_error(const ParamSpec& s) {
  std::string text = std::string(s.name) + ": " + range_text(s);
  if (*s.where) text += std::string(" ") + s.where;
  return text;
}

bool in_range(const ParamSpec& s, double v) {
  if (!std::isfinite(v)) return false;
  if (s.integer && v != std::floor(v)) return false;
  return (s.min_open ? v > s.min : v >= s.min) && v <= s.max;
}

std::string check(const ParamSpec& s, double v) { return in_range(s, v) ? std::string() : param_error(s); }

double param_from_json(const ParamSpec& s, const nlohmann::json& v) {
  // An unsigned JSON integer past 2^63 converts to a double above any max: refused, not wrapped.
  const bool number = s.integer ? v.is_number_integer() : v.is_number();
  if (!number) throw std::invalid_argument(param_error(s));
  const double x = v.is_number_unsigned() ? static_cast<double>(v.get<std::uint64_t>())
                   : v.is_number_integer() ? static_cast<double>(v.get<std::int64_t>())
                                            : v.get<double>();
  // Above 2^53 the conversion may round down onto max: compare the integer itself there.
  if (s.integer && v.is_number_unsigned() && v.get<std::uint64_t>() > 9007199254740991ull && s.max <= 9007199254740991.0)
    throw std::invalid_argument(param_error(s));
  if (!in_range(s, x)) throw std::invalid_argument(param_error(s));
  return x;
}

}  // namespace csl
