// A JSON number literal as the exact decimal it denotes, for checks that must hold at every precision:
// a limit checked on a rounded double would pass 1.00000000000000001 as 1 while 50 digits compute with
// more than 1.
#pragma once

#include <string>
#include <string_view>

namespace impact3d::case_format {

struct Decimal {
  bool negative = false;
  std::string digits;  // no leading or trailing zeros; empty for zero
  long exponent = 0;   // value = digits x 10^exponent; saturates far beyond any accepted literal

  bool zero() const { return digits.empty(); }
  bool operator==(const Decimal& o) const = default;
};

// `literal` must be JSON number syntax, -?int(.frac)?([eE][+-]?exp)?, as the JSON parser accepted it.
Decimal parse_decimal(std::string_view literal);

// The exponent as written after e/E (0 when there is none), saturating at +-10^15.
long written_exponent(std::string_view literal);

// -1, 0, 1 as a <, ==, > b (signed values; -0 equals 0).
int compare(const Decimal& a, const Decimal& b);

// Compares magnitudes |a| against |b|.
int compare_magnitude(const Decimal& a, const Decimal& b);

}  // namespace impact3d::case_format
