// planar_norm at double against the exact length of the same pair at 50 digits, across the whole
// exponent range, and against std::hypot where it hands over to it (the ends of the range, infinities,
// NaN).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>

#include "impact3d/scalar/autodiff.hpp"
#include "impact3d/scalar/ball.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "impact3d/scalar/planar_norm.hpp"
#include "support.hpp"

namespace check_planar_norm {

using namespace impact3d;
using namespace impact3d::test;

namespace {

// |planar_norm(a, b) - |(a, b)|| / |(a, b)|, the reference at 50 digits from the doubles themselves.
double relative_error(double a, double b) {
  const mp::float50 A(a), B(b);
  const mp::float50 exact = sqrt(A * A + B * B);
  if (exact == 0) return planar_norm(a, b) == 0 ? 0 : 1;
  return static_cast<double>(abs(mp::float50(planar_norm(a, b)) - exact) / exact);
}

double random_double(std::mt19937_64& g, int min_exponent, int max_exponent) {
  std::uniform_real_distribution<double> mantissa(1, 2);
  std::uniform_int_distribution<int> exponent(min_exponent, max_exponent);
  std::bernoulli_distribution negative(0.5);
  const int e = exponent(g);  // the last first, as GCC took the call's arguments
  const double x = std::ldexp(mantissa(g), e);
  return negative(g) ? -x : x;
}

}  // namespace

TEST_CASE("planar_norm is within eps of the exact length over the exponent range", "[planar_norm]") {
  // Inside the root's range: a*a and b*b round once each (u = eps/2 relative) and so, both being
  // positive, does their sum: (1 + u)^2 at most; the root halves that to 1 + u and rounds once more,
  // (1 + u)^2 = 1 + 2u + u^2 in all, eps (1 + eps / 4); a smaller square that underflows is under 2^-120
  // of the sum. Outside the range glibc's hypot, listed at one ulp: at most 2u relative. The 50-digit
  // reference adds 1e-50. Bound: eps (1 + eps). It cannot tell the root's bound from one ulp; it does
  // catch a range limit in the wrong place (an overflow, an underflow to zero or to a subnormal's few
  // digits), a lost NaN, and an argument dropped.
  std::mt19937_64 g(29);
  int checked = 0, by_root = 0, by_hypot = 0;
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    // Pairs of like and of far-apart magnitudes, from subnormal to near the largest double; the larger
    // normal, so that the length is (a subnormal length has fewer digits than eps speaks for).
    const double a = random_double(g, -1000, 990);
    const double b = k % 2 ? random_double(g, -1074, 1022) : std::ldexp(a, int(g() % 61) - 30);
    const double larger = std::fmax(std::fabs(a), std::fabs(b));
    if (larger >= 0x1p-450 && larger <= 0x1p500) ++by_root;
    else ++by_hypot;
    const double e = relative_error(a, b);
    worst = std::fmax(worst, e);
    CHECK(e <= eps * (1 + eps));
    ++checked;
  }
  CHECK(checked == 20000);
  // The root's range is about half the exponents drawn, and both sides see thousands of pairs.
  CHECK(by_root > 5000);
  CHECK(by_hypot > 5000);
  INFO("worst relative error " << worst / eps << " eps");
  CHECK(worst <= eps * (1 + eps));
}

TEST_CASE("planar_norm at the ends of the root's range and beyond", "[planar_norm]") {
  const double big = 0x1p500, small = 0x1p-450, huge = std::numeric_limits<double>::max();
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  // Each a length that is a normal double, so that eps speaks for it.
  for (double x : {big, std::nextafter(big, inf), small, std::nextafter(small, 0.0), huge / 2, 0x1p-1022}) {
    CHECK(relative_error(x, x) <= eps * (1 + eps));
    CHECK(relative_error(x, -x / 3) <= eps * (1 + eps));
    CHECK(relative_error(x, 0x1p-1074) <= eps * (1 + eps));
  }
  // Where a bare root would overflow or underflow, the length is still the exact one's rounding.
  CHECK(planar_norm(huge, huge) == inf);  // the exact length is above the largest double
  CHECK(std::isfinite(planar_norm(huge / 2, huge / 2)));
  CHECK(planar_norm(0x1p-1074, 0x1p-1074) > 0);
  CHECK(planar_norm(0.0, -0.0) == 0);
  CHECK(planar_norm(3.0, 4.0) == 5);
  // IEEE hypot: an infinity wins over a NaN.
  CHECK(planar_norm(inf, nan) == inf);
  CHECK(planar_norm(nan, -inf) == inf);
  CHECK(std::isnan(planar_norm(nan, 1.0)));
  CHECK(std::isnan(planar_norm(1.0, nan)));
  CHECK(std::isnan(planar_norm(nan, nan)));
}

TEST_CASE("planar_norm at other scalars is their own hypot", "[planar_norm]") {
  const mp::float50 a("0.3"), b("-1.7");
  CHECK(planar_norm(a, b) == hypot(a, b));
  CHECK(planar_norm(0.3L, -1.7L) == std::hypot(0.3L, -1.7L));
  // A ball's (ADL in impact3d): it encloses the exact length of its arguments, 5 for (3, 4) and
  // sqrt(0.09 + 2.89) for the decimals 0.3 and -1.7.
  const Ball five = planar_norm(Ball(3.0), Ball(-4.0));
  CHECK((five - Ball(5.0)).contains_zero());
  const Ball apart = planar_norm(Ball("0.3"), Ball("-1.7")) - sqrt(Ball("2.98"));
  CHECK(apart.contains_zero());
  CHECK(apart.upper_double() < 1e-60);  // 256-bit balls: radii near 1e-76
  // A dual's (ADL in Eigen): the double path's value, and the derivatives (a, b) / |(a, b)|.
  Dual x(3.0), y(-4.0);
  x.derivatives() = Dual::DerType::Unit(0);
  y.derivatives() = Dual::DerType::Unit(1);
  const Dual h = planar_norm(x, y);
  CHECK(h.value() == planar_norm(3.0, -4.0));
  CHECK(h.derivatives()[0] == 0.6);  // 3/5 and -4/5, each one correctly rounded division
  CHECK(h.derivatives()[1] == -0.8);
}

}  // namespace check_planar_norm
