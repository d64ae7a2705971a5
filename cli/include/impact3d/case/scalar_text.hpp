// Decimal text <-> Scalar without passing through a narrower type.
#pragma once

#include <cstdlib>
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
  } else {
    return Scalar(text);
  }
}

// Every significant digit the type holds (max_digits10: 17 for double), so the text reads back exactly.
template <typename Scalar>
std::string scalar_to_text(const Scalar& x, int digits = std::numeric_limits<Scalar>::max_digits10) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(digits);
  os << x;
  return os.str();
}

}  // namespace impact3d::io
