// scalar_to_text prints double and long double through std::to_chars (io/scalar_text.hpp) and every
// other type through a classic-locale stream; the two must give the same text, since `solve` and `batch`
// print every result number this way and the contract fixes the digits (%.17g for double). Random bit
// patterns (subnormals, infinities and NaNs among them) and ordinary magnitudes, at every digit count
// the reports use.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

#include "impact3d/io/scalar_text.hpp"

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
