// Decimal text <-> Scalar without passing through a narrower type.
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <limits>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <boost/multiprecision/cpp_int.hpp>

#include "impact3d/case_format/decimal.hpp"
#include "impact3d/case_format/format_double.hpp"
#include "impact3d/case_format/json_text.hpp"
#include "impact3d/case_format/limits.hpp"

namespace impact3d::case_format {

template <typename Scalar>
Scalar scalar_from_text(const std::string& text) {
  if constexpr (std::is_same_v<Scalar, double>) {
    // from_chars is correctly rounded like strtod, at a third of the cost; strtod keeps the last word on
    // what from_chars does not take whole (out of range, text it does not read).
    double x;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), x);
    if (r.ec == std::errc() && r.ptr == text.data() + text.size()) return x;
    return std::strtod(text.c_str(), nullptr);
  } else if constexpr (std::is_same_v<Scalar, long double>) {
    return std::strtold(text.c_str(), nullptr);
  } else if constexpr (std::numeric_limits<Scalar>::is_exact) {
    // The exact fraction the literal denotes; the reader bounds the exponent (limits.hpp), and this
    // refuses anything beyond it rather than build a power of ten of any size.
    const Decimal d = parse_decimal(text);
    if (d.zero()) return Scalar(0);
    constexpr long kMaxExponent = 4 * limits::kExponent;
    if (d.exponent > kMaxExponent || d.exponent < -kMaxExponent)
      throw std::invalid_argument("scalar_from_text: exponent beyond the input limits");
    using Int = boost::multiprecision::cpp_int;
    const Int power = boost::multiprecision::pow(Int(10), static_cast<unsigned>(d.exponent < 0 ? -d.exponent : d.exponent));
    Scalar value = d.exponent >= 0 ? Scalar(Int(d.digits) * power) : Scalar(Int(d.digits)) / Scalar(power);
    return d.negative ? Scalar(-value) : value;
  } else {
    return Scalar(text);
  }
}

// Every significant digit the type holds (max_digits10: 17 for double), so the text reads back exactly,
// appended to `out`. The standard types go through std::to_chars, which formats as printf's %.Ng does,
// the same text a classic-locale stream prints, at a twentieth of the cost (a double at 17 digits by
// format_g17, at a fifth of that); the multiprecision types through a stream.
template <typename Scalar>
void append_scalar(std::string& out, const Scalar& x, int digits = std::max(std::numeric_limits<Scalar>::max_digits10, 1));

// The same into a writer's text: a double at 17 digits formatted in place, any other through a string.
template <typename Scalar>
void append_scalar(JsonText& out, const Scalar& x, int digits = std::max(std::numeric_limits<Scalar>::max_digits10, 1)) {
  if constexpr (std::is_same_v<Scalar, double>) {
    if (digits == 17) {
      out.commit(format_g17(out.room(32), x));
      return;
    }
  }
  thread_local std::string text;
  text.clear();
  append_scalar(text, x, digits);
  out.append(text);
}

template <typename Scalar>
void append_scalar(std::string& out, const Scalar& x, int digits) {
  // A ball (scalar/ball.hpp) is written in its thread's text form (BallText), below.
  if constexpr (std::is_same_v<Scalar, double>) {
    if (digits == 17) {
      char buf[32];
      out.append(buf, format_g17(buf, x));
      return;
    }
  }
  if constexpr (std::is_same_v<Scalar, double> || std::is_same_v<Scalar, long double>) {
    char buf[128];
    const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, digits);
    if (r.ec == std::errc()) {
      out.append(buf, r.ptr);
      return;
    }
  }
  if constexpr (requires { x.append_text(out, digits); }) {
    x.append_text(out, digits);
  } else {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os.precision(digits);
    os << x;
    out += os.str();
  }
}

template <typename Scalar>
std::string scalar_to_text(const Scalar& x, int digits = std::max(std::numeric_limits<Scalar>::max_digits10, 1)) {
  std::string out;
  append_scalar(out, x, digits);
  return out;
}

}  // namespace impact3d::case_format
