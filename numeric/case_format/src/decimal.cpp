#include "impact3d/case_format/decimal.hpp"

#include <cctype>

namespace impact3d::case_format {
namespace {

constexpr long kSaturate = 1000000000000000L;

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

}  // namespace

long written_exponent(std::string_view s) {
  // A plain loop: find_first_of calls memchr once per character of the literal.
  std::size_t e = 0;
  while (e < s.size() && s[e] != 'e' && s[e] != 'E') ++e;
  if (e == s.size()) return 0;
  std::size_t i = e + 1;
  bool negative = false;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
  long value = 0;
  for (; i < s.size() && digit(s[i]); ++i) value = value >= kSaturate ? kSaturate : value * 10 + (s[i] - '0');
  return negative ? -value : value;
}

Decimal parse_decimal(std::string_view s) {
  Decimal d;
  std::size_t i = 0;
  if (i < s.size() && s[i] == '-') d.negative = true, ++i;
  long exponent = 0;
  for (; i < s.size() && digit(s[i]); ++i) d.digits += s[i];
  if (i < s.size() && s[i] == '.')
    for (++i; i < s.size() && digit(s[i]); ++i) d.digits += s[i], --exponent;
  const long written = written_exponent(s);
  const auto first = d.digits.find_first_not_of('0');
  if (first == std::string::npos) return Decimal{};
  d.digits.erase(0, first);
  const auto last = d.digits.find_last_not_of('0');
  exponent += static_cast<long>(d.digits.size() - 1 - last);
  d.digits.erase(last + 1);
  d.exponent = exponent + written;  // |exponent| <= literal length, |written| <= 10^15: no overflow
  return d;
}

int compare_magnitude(const Decimal& a, const Decimal& b) {
  if (a.zero() || b.zero()) return a.zero() == b.zero() ? 0 : (a.zero() ? -1 : 1);
  // The value lies in [10^(order - 1), 10^order).
  const long oa = a.exponent + static_cast<long>(a.digits.size()), ob = b.exponent + static_cast<long>(b.digits.size());
  if (oa != ob) return oa < ob ? -1 : 1;
  const int c = a.digits.compare(b.digits);  // same order: the digit strings compare as left-aligned fractions
  return c < 0 ? -1 : (c > 0 ? 1 : 0);
}

int compare(const Decimal& a, const Decimal& b) {
  const bool na = a.negative && !a.zero(), nb = b.negative && !b.zero();
  if (na != nb) return na ? -1 : 1;
  const int m = compare_magnitude(a, b);
  return na ? -m : m;
}

}  // namespace impact3d::case_format
