// Decimal text <-> Scalar without passing through a narrower type.
#pragma once

#include <cctype>
#include <cstdlib>

#include <boost/multiprecision/cpp_int.hpp>
#include <algorithm>
#include <limits>
#include <locale>
#include <sstream>
#include <string>
#include <type_traits>

namespace impact3d::io {

template <typename Scalar>
Scalar scalar_from_text(const std::string& text) {
  if constexpr (std::is_same_v<Scalar, double>) {
    return std::strtod(text.c_str(), nullptr);
  } else if constexpr (std::is_same_v<Scalar, long double>) {
    return std::strtold(text.c_str(), nullptr);
  } else if constexpr (std::numeric_limits<Scalar>::is_exact) {
    // A JSON number -?int(.frac)?([eE][+-]?exp)? as the exact fraction it denotes.
    std::string digits;
    long exponent = 0;
    std::size_t i = 0;
    const bool negative = !text.empty() && text[0] == '-';
    if (negative) ++i;
    for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i) digits += text[i];
    if (i < text.size() && text[i] == '.')
      for (++i; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i, --exponent) digits += text[i];
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) exponent += std::stol(text.substr(i + 1));
    using Int = boost::multiprecision::cpp_int;
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));  // a leading 0 would mean octal
    Scalar value = Scalar(Int(digits.empty() ? "0" : digits));
    const Scalar ten = Scalar(Int(10));
    for (long k = 0; k < exponent; ++k) value *= ten;
    for (long k = 0; k > exponent; --k) value /= ten;
    return negative ? Scalar(-value) : value;
  } else {
    return Scalar(text);
  }
}

// Every significant digit the type holds (max_digits10: 17 for double), so the text reads back exactly.
template <typename Scalar>
std::string scalar_to_text(const Scalar& x, int digits = std::max(std::numeric_limits<Scalar>::max_digits10, 1)) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(digits);
  os << x;
  return os.str();
}

}  // namespace impact3d::io
