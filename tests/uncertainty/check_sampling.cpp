// The sampling transforms (uncertainty/portable_math.hpp) against 50-digit Boost.Multiprecision, an
// independent route: portable_log and portable_exp against log and exp of the same double, the normal
// quantile judged by Phi at 50 digits (the error in x is (Phi(x) - p) / phi(x)); and the uniform draws
// (philox.hpp) as the documentation states them. Errors in ulps of the exact value, worst case reported.
#include <cmath>
#include <cstdint>
#include <limits>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>

#include "impact3d/uncertainty/philox.hpp"
#include "impact3d/uncertainty/portable_math.hpp"

namespace check_sampling {

namespace {

using namespace impact3d::uncertainty;
using big = boost::multiprecision::cpp_bin_float_50;

// |x - exact| in units of the last place of the double nearest to exact.
double ulps(double x, const big& exact) {
  const double near = static_cast<double>(exact);
  const double ulp = std::nextafter(std::fabs(near), std::numeric_limits<double>::infinity()) - std::fabs(near);
  return static_cast<double>(abs(big(x) - exact) / big(ulp));
}

// A double spread over many binades: mantissa and exponent from two draws.
double spread(std::uint64_t i, int lo, int hi) {
  const double m = 1 + uniform_open(7, i, 0);
  const int e = lo + static_cast<int>(uniform_open(7, i, 1) * (hi - lo + 1));
  return std::ldexp(m, e);
}

// The worst error over the points checked, and where it was.
struct Worst {
  double ulps = 0, at = 0;
  int checked = 0;
  void add(double err, double x) {
    if (err > ulps) ulps = err, at = x;
    ++checked;
  }
};

}  // namespace

// Tolerances, in ulps of the exact value:
// - log, 1: fdlibm's arrangement keeps the large terms exact, so the result carries the rounding of
//   the last subtraction and a fraction of an ulp from the small terms (truncation below 2^-56);
// - exp, 2: the series is summed in double and scaled exactly; its last addition rounds once, the
//   reduction x - k ln 2 and the earlier terms add up to an ulp at most;
// - the quantile, 8: AS241's rational approximations are published as accurate to about 1e-16 (half an
//   ulp), and their evaluation in double and the tail's log and square root add a few ulps (4.9 the
//   worst seen). Any of these is ten orders of magnitude below the sampling error of a Monte Carlo run
//   (1 / sqrt(10^7) = 3e-4); what the test guards against is a wrong coefficient or branch, which costs
//   1e-6 or more;
// - Phi and its tail, 16: two exponentials of 2 ulps each (e^(-x^2/2) with x^2 split so that its large
//   part is exact), and Cody's rational, the series or the continued fraction, each truncated below
//   2^-56 and summed over positive terms (a few ulps); the rational's argument x / sqrt 2 is rounded,
//   but e^(y^2) erfc(y) changes by at most its own relative change in y. About 10 ulps in all; 5.7 the
//   worst seen.
TEST_CASE("portable_log is within 1 ulp of the 50-digit logarithm") {
  Worst w;
  for (std::uint64_t i = 0; i < 20000; ++i) {
    const double x = i % 4 == 0 ? 1 + (uniform_open(3, i, 0) - 0.5) / 8 : spread(i, -1070, 1020);
    w.add(ulps(portable_log(x), log(big(x))), x);
  }
  INFO("worst " << w.ulps << " ulp at x = " << w.at);
  CHECK(w.checked == 20000);
  CHECK(w.ulps <= 1.0);
  CHECK(portable_log(1.0) == 0.0);
  CHECK(std::isnan(portable_log(-1.0)));
  CHECK(portable_log(0.0) == -std::numeric_limits<double>::infinity());
}

TEST_CASE("portable_exp is within 2 ulps of the 50-digit exponential") {
  Worst w;
  for (std::uint64_t i = 0; i < 20000; ++i) {
    // The whole range where e^x is finite and not zero, subnormal results included, and near 0.
    const double x = i % 2 ? -745 + 1454.7 * uniform_open(5, i, 0) : 8 * (uniform_open(5, i, 0) - 0.5);
    w.add(ulps(portable_exp(x), exp(big(x))), x);
  }
  INFO("worst " << w.ulps << " ulp at x = " << w.at);
  CHECK(w.checked == 20000);
  CHECK(w.ulps <= 2.0);
  CHECK(portable_exp(0.0) == 1.0);
  CHECK(portable_exp(710.0) == std::numeric_limits<double>::infinity());
  CHECK(portable_exp(-746.0) == 0.0);
}

TEST_CASE("normal_quantile is within 8 ulps of the 50-digit quantile, from the centre to the last uniform draw") {
  const big root_two_pi = sqrt(2 * boost::math::constants::pi<big>());
  double worst = 0, at = 0;
  int checked = 0;
  auto check = [&](double p) {
    const double x = normal_quantile(p);
    const big X(x);
    const big Phi = erfc(-X / sqrt(big(2))) / 2, phi = exp(-X * X / 2) / root_two_pi;
    const big exact = X - (Phi - big(p)) / phi;  // one Newton step from x: its error is O((x - exact)^2)
    const double err = ulps(x, exact);
    if (err > worst) worst = err, at = p;
    ++checked;
  };
  for (std::uint64_t i = 0; i < 20000; ++i) check(uniform_open(11, i, 0));
  for (int k = 2; k <= 53; ++k) check(std::ldexp(1.0, -k)), check(1 - std::ldexp(1.0, -k));
  check(0x1p-53);  // the smallest uniform draw, (0 + 1/2) / 2^52
  INFO("worst " << worst << " ulp at p = " << at);
  CHECK(checked == 20000 + 2 * 52 + 1);
  CHECK(worst <= 8.0);
  CHECK(normal_quantile(0.5) == 0.0);
  CHECK(std::isnan(normal_quantile(0.0)));
  CHECK(std::isnan(normal_quantile(1.0)));
}

TEST_CASE("normal_cdf and its upper tail are within 16 ulps of 50-digit erfc, down to 1e-300") {
  double worst = 0, at = 0;
  int checked = 0;
  for (std::uint64_t i = 0; i < 20000; ++i) {
    const double x = i % 2 ? -37 + 45 * uniform_open(13, i, 0) : 6 * (uniform_open(13, i, 0) - 0.5);
    const big exact = erfc(-big(x) / sqrt(big(2))) / 2, tail = erfc(big(x) / sqrt(big(2))) / 2;
    const double e1 = ulps(normal_cdf(x), exact), e2 = ulps(normal_upper_tail(x), tail);
    if (std::max(e1, e2) > worst) worst = std::max(e1, e2), at = x;
    ++checked;
  }
  for (const double x : {0.0, 2.5, -2.5, 2.4999999999999996, -37.0, 8.0})
    worst = std::max(worst, ulps(normal_cdf(x), erfc(-big(x) / sqrt(big(2))) / 2)), ++checked;
  INFO("worst " << worst << " ulp at x = " << at);
  CHECK(checked == 20006);
  CHECK(worst <= 16.0);
  CHECK(normal_cdf(0.0) == 0.5);
  CHECK(normal_cdf(-40.0) == 0.0);
  CHECK(normal_cdf(40.0) == 1.0);
}

TEST_CASE("uniform draws are (k + 1/2) / 2^52, inside (0, 1), and their normal scores have the normal's moments") {
  int checked = 0;
  double sum = 0, sum2 = 0, below = 0;
  const int n = 200000;
  for (std::uint64_t i = 0; i < static_cast<std::uint64_t>(n); ++i) {
    const double u = uniform_open(42, i, 3);
    const double k = u * 0x1p52 - 0.5;
    REQUIRE(k == std::floor(k));
    REQUIRE(u > 0);
    REQUIRE(u < 1);
    const double z = normal_quantile(u);
    sum += z, sum2 += z * z, below += z < 1.959963984540054;
    ++checked;
  }
  CHECK(checked == n);
  // Sampling error: the mean's standard error is 1/sqrt(n), the variance's sqrt(2/n), the fraction's
  // sqrt(0.975 0.025 / n); 5 of them is a one-in-a-million miss, fixed by the seed.
  const double mean = sum / n, var = sum2 / n - mean * mean;
  CHECK(std::fabs(mean) < 5 / std::sqrt(double(n)));
  CHECK(std::fabs(var - 1) < 5 * std::sqrt(2.0 / n));
  CHECK(std::fabs(below / n - 0.975) < 5 * std::sqrt(0.975 * 0.025 / n));
  // Another seed, sample or input gives another draw.
  CHECK(uniform_open(42, 0, 3) != uniform_open(43, 0, 3));
  CHECK(uniform_open(42, 0, 3) != uniform_open(42, 1, 3));
  CHECK(uniform_open(42, 0, 3) != uniform_open(42, 0, 4));
  CHECK(uniform_open(42, 0, 3, 0) != uniform_open(42, 0, 3, 1));
}

}  // namespace check_sampling
