// scalar_to_text prints double and long double through std::to_chars (io/scalar_text.hpp) and every
// other type through a classic-locale stream; the two must give the same text, since `solve` and `batch`
// print every result number this way and the contract fixes the digits (%.17g for double). Random bit
// patterns (subnormals, infinities and NaNs among them) and ordinary magnitudes, at every digit count
// the reports use.
#include <catch2/catch.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <utility>

#include "impact3d/io/json_writer.hpp"
#include "impact3d/io/scalar_text.hpp"
#include "impact3d/numeric/ball.hpp"
#include "impact3d/numeric/scalars.hpp"

namespace {

template <typename T>
std::string streamed(const T& x, int digits) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(digits);
  os << x;
  return os.str();
}

}  // namespace

TEST_CASE("scalar_to_text of double and long double is the classic stream's text", "[io]") {
  std::mt19937_64 g(11);
  int compared = 0, mismatched = 0;
  auto check = [&](auto x, int digits) {
    ++compared;
    if (impact3d::io::scalar_to_text(x, digits) != streamed(x, digits)) {
      ++mismatched;
      UNSCOPED_INFO(streamed(x, digits));
    }
  };
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t bits = g();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (i % 2) x = std::ldexp(static_cast<double>(g() % 1000000) / 7.0, static_cast<int>(g() % 80) - 40);
    for (int d : {17, 10, 6, 1}) check(x, d);
    for (int d : {21, 18, 10}) check(static_cast<long double>(x) / 3.0L, d);
  }
  for (double x : {0.0, -0.0, HUGE_VAL, -HUGE_VAL, std::nan(""), 5e-324, 1.0, 1e16, 1e17, 123456789012345678.0})
    for (int d : {17, 10, 1}) check(x, d);
  CHECK(mismatched == 0);
  CHECK(compared == 200000 * 7 + 10 * 3);
}

// format_g17 decides the rounding from a 192-bit product and leaves only near-ties to std::to_chars
// (io/format_double.hpp); it must give std::to_chars's text everywhere. Beside random bit patterns: every
// binade's ends, the neighbours of each power of ten (where the digit count changes), exact ties at the
// 18th digit (n + 0.25 and n + 0.75 for 16-digit n below 2^51, where quarters are representable; rounded
// to even; below 2^50 the guess of the decimal exponent is one short, and the 18-digit product decides),
// and scaled random integers.
TEST_CASE("format_g17 is std::to_chars at 17 digits", "[io]") {
  std::mt19937_64 g(17);
  int compared = 0, mismatched = 0;
  auto check = [&](double x) {
    char mine[32], theirs[32];
    const std::string a(mine, impact3d::io::format_g17(mine, x));
    const std::string b(theirs, std::to_chars(theirs, theirs + sizeof theirs, x, std::chars_format::general, 17).ptr);
    ++compared;
    if (a != b) {
      ++mismatched;
      UNSCOPED_INFO(a << " != " << b);
    }
  };
  for (int i = 0; i < 1000000; ++i) {
    const std::uint64_t bits = g();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    check(x);
  }
  for (int e = -1074; e <= 1023; ++e) {
    const double lo = std::ldexp(1.0, e);
    check(lo);
    check(std::nextafter(lo, 0.0));
    check(-std::nextafter(lo, HUGE_VAL));
  }
  for (int p = -323; p <= 308; ++p) {
    const double t = std::strtod(("1e" + std::to_string(p)).c_str(), nullptr);  // stod refuses subnormals
    for (double x = t, n = 0; n < 4; ++n) x = std::nextafter(x, 0.0), check(x);
    for (double x = t, n = 0; n < 4; ++n) check(x), x = std::nextafter(x, HUGE_VAL);
  }
  for (int i = 0; i < 100000; ++i) {
    const double n = static_cast<double>(1000000000000000ULL + g() % 1251799813685248ULL);  // [1e15, 2^51)
    check(n + 0.25);
    check(n + 0.75);
    check(std::ldexp(static_cast<double>(g() >> 11), static_cast<int>(g() % 200) - 100));
  }
  for (double x : {0.0, -0.0, HUGE_VAL, -HUGE_VAL, std::nan(""), 5e-324, 1.7976931348623157e308, 1e16, 1e17, 975.0})
    check(x);
  CHECK(mismatched == 0);
  CHECK(compared == 1000000 + 3 * 2098 + 8 * 632 + 3 * 100000 + 10);
}

// The JSON writer writes a non-finite number as null, telling it by the text's first letter (after a
// sign): every scalar type's text of an infinity or a NaN, at every digit count, is null there, and every
// finite text is written as it is.
TEST_CASE("the JSON writer writes non-finite numbers as null and finite ones as their text, at every scalar type", "[io]") {
  using impact3d::io::JsonWriter;
  int compared = 0;
  auto written = [](auto x, int digits) {
    JsonWriter w(true);
    w.number([&](std::string& out) { impact3d::io::append_scalar(out, x, digits); });
    std::string s = std::move(w).str();
    s.pop_back();  // the newline
    return s;
  };
  auto check_type = [&](auto zero) {
    using T = decltype(zero);
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    for (int digits : {std::numeric_limits<T>::max_digits10, 17, 6, 3}) {
      for (const T& x : {inf, T(-inf), nan, T(-nan)}) {
        CHECK(written(x, digits) == "null");
        ++compared;
      }
      for (const T& x : {T(0), T(-T(0)), T(1) / T(3), T(-2) / T(7), T(1e300), T(-1e-300), std::numeric_limits<T>::denorm_min()}) {
        CHECK(written(x, digits) == impact3d::io::scalar_to_text(x, digits));
        ++compared;
      }
    }
  };
  [&]<std::size_t... I>(std::index_sequence<I...>) { (check_type(impact3d::ScalarAt<I>(0)), ...); }(std::make_index_sequence<impact3d::kScalarCount>());
  CHECK(compared == static_cast<int>(impact3d::kScalarCount) * 4 * 11);
  // A ball: NaN when not finite (one not containing a finite real), its enclosure text otherwise.
  CHECK(written(impact3d::Ball(std::numeric_limits<double>::infinity()), 17) == "null");
  CHECK(written(impact3d::Ball(1.0) / impact3d::Ball(3.0), 17) != "null");
}
