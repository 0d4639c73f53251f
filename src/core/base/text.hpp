#pragma once
// Text from users, read and echoed the same way on every surface (scene files, the CLI's
// arguments, the app's API, links): one syntax for numbers, and messages that stay one line.
//
// Numbers are plain decimals, exactly what the page's links accept (web/lab-url.js, NUMBER):
//   -?(digits[.digits*] | .digits)([eE][-+]?digits)?
// No leading '+' or spaces, no hexadecimal, no "inf" or "nan": strtod alone takes all of
// those, and a value a script passes must mean the same to the CLI, the app and a link.
#include <optional>
#include <string>
#include <string_view>

namespace csl {

/// Whether `text` is a number in the syntax above (the value may still overflow).
bool is_decimal_syntax(std::string_view text);

/// The value of a decimal in the syntax above, if it is finite. An underflow (1e-400) is a
/// number: it rounds to a subnormal or to 0, as a JSON parser reads it.
std::optional<double> parse_decimal(std::string_view text);

/// The value of -?digits, if it fits a long long.
std::optional<long long> parse_integer(std::string_view text);

/// `text` with every control character escaped (\n, \t, \r, \xNN, and the C1 controls of
/// UTF-8 as \u0080..\u009f), so that a message quoting untrusted text stays one printable
/// line; longer than `max` bytes, it is cut (on a UTF-8 boundary) and ends in "...".
std::string printable(std::string_view text, std::size_t max = std::string_view::npos);

/// `text` without the white space around it (isspace() in the C locale: a typed answer as it
/// is judged).
std::string trim(std::string_view text);

}  // namespace csl

namespace csl {

/// `v` rounded to `digits` significant digits as the lab's descriptions print it ("%.4g" with
/// no exponent for ordinary sizes: 1.234, 0.02, 1235): what a screen reader reads out, short
/// and the same in every build. "-0" prints as "0".
std::string significant(double v, int digits = 4);

}  // namespace csl
