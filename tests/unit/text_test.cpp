// The one number syntax of every surface (core/base/text.hpp) and one-line messages.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "core/base/text.hpp"

TEST_CASE("decimals: what links accept, nothing strtod adds") {
  for (const char* ok : {"0", "-0", "1", "0.5", ".5", "5.", "-.25", "1e3", "1E-3", "2.5e+7", "007", "1e-310"})
    CHECK_MESSAGE(csl::parse_decimal(ok).has_value(), ok);
  CHECK(*csl::parse_decimal("-.25") == -0.25);
  CHECK(*csl::parse_decimal("1e-400") == 0.0);  // an underflow is a number
  for (const char* bad : {"", " 1", "1 ", "+1", "0x10", "0x1p-3", "inf", "nan", "1e", "e3", ".", "-", "1.2.3", "1e400",
                          "1,5", "1e+", "--1", "\t2"})
    CHECK_MESSAGE(!csl::parse_decimal(bad).has_value(), bad);
  CHECK_FALSE(csl::is_decimal_syntax("1e5x"));
}

TEST_CASE("integers: digits with an optional minus, within long long") {
  CHECK(*csl::parse_integer("42") == 42);
  CHECK(*csl::parse_integer("-7") == -7);
  CHECK(*csl::parse_integer("0009") == 9);
  for (const char* bad : {"", " 5", "5 ", "+5", "0x10", "5.0", "1e3", "-", "99999999999999999999"})
    CHECK_MESSAGE(!csl::parse_integer(bad).has_value(), bad);
}

TEST_CASE("printable: control characters escaped, UTF-8 kept, long text cut on a character") {
  CHECK(csl::printable("a\nb\tc\rd") == "a\\nb\\tc\\rd");
  CHECK(csl::printable("\x1b[31mred\x7f") == "\\x1b[31mred\\x7f");
  CHECK(csl::printable(std::string("nul\0x", 5)) == "nul\\x00x");
  CHECK(csl::printable("\xC2\x9B" "2J") == "\\u009b2J");  // CSI as a C1 control
  CHECK(csl::printable("θ₁ × S¹") == "θ₁ × S¹");
  CHECK(csl::printable("abcdef", 3) == "abc...");
  CHECK(csl::printable("θθθ", 3) == "θ...");  // not inside the second θ
}
