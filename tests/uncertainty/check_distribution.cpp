// The quantile functions of the uncertainty file's distributions (uncertainty/distribution.hpp) against
// the same quantiles at 50 digits (Boost.Multiprecision: closed forms for uniform and triangular, Newton
// on 50-digit erfc for the normal family), on seeded uniform draws, each within a bound derived from the
// errors of its parts (portable_math.hpp: the normal quantile 8 ulps, Phi 16, exp 2); and discrete
// values drawn at the frequencies of their weights.
#include <cmath>
#include <cstdint>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>

#include "impact3d/uncertainty/distribution.hpp"
#include "impact3d/uncertainty/philox.hpp"

namespace check_distribution {

namespace {

using namespace impact3d::uncertainty;
using big = boost::multiprecision::cpp_bin_float_50;
using Kind = Distribution::Kind;
constexpr double eps = 0x1p-52;

big Phi(const big& z) { return erfc(-z / sqrt(big(2))) / 2; }
big phi(const big& z) { return exp(-z * z / 2) / sqrt(2 * boost::math::constants::pi<big>()); }
// The z with Phi(z) = p, by Newton from a double start (quadratic: three steps pass 50 digits).
big Phi_inverse(const big& p, double start) {
  big z = start;
  for (int i = 0; i < 4; ++i) z -= (Phi(z) - p) / phi(z);
  return z;
}

Distribution make(Kind k, double a, double b = 0, double c = 0, double d = 0) {
  Distribution x;
  x.kind = k;
  switch (k) {
    case Kind::normal: x.mean = a, x.sd = b; break;
    case Kind::truncated_normal: x.mean = a, x.sd = b, x.min = c, x.max = d; break;
    case Kind::uniform: x.min = a, x.max = b; break;
    case Kind::triangular: x.min = a, x.mode = b, x.max = c; break;
    case Kind::lognormal: x.median = a, x.sigma = b; break;
    case Kind::discrete: break;
  }
  return x;
}

// The exact quantile, and the error the double may carry, derived from its parts.
struct Expected {
  big x;
  double allowed;
};

Expected expected(const Distribution& d, double u, double got) {
  const big U(u);
  switch (d.kind) {
    case Kind::normal: {
      const big z = Phi_inverse(U, (got - d.mean) / d.sd);
      // z within 8 ulps, then mean + sd z rounds twice.
      const double az = std::fabs(static_cast<double>(z));
      return {d.mean + d.sd * z, eps * (8 * d.sd * az + 2 * (std::fabs(d.mean) + d.sd * az))};
    }
    case Kind::lognormal: {
      const big z = Phi_inverse(U, std::log(got / d.median) / d.sigma);
      const big x = d.median * exp(d.sigma * z);
      // sigma z carries 8 ulps of z and a rounding; exp 2 ulps; the product a rounding.
      const double rel = eps * (9 * d.sigma * std::fabs(static_cast<double>(z)) + 4);
      return {x, rel * static_cast<double>(x)};
    }
    case Kind::truncated_normal: {
      const big a = (big(d.min) - d.mean) / d.sd, b = (big(d.max) - d.mean) / d.sd;
      const big pa = Phi(a), pb = Phi(b);
      const big z = Phi_inverse(pa + U * (pb - pa), (got - d.mean) / d.sd);
      // The window's ends: the double a, b carry a rounding each; Phi of them 16 ulps of the larger
      // probability of the side worked on (the upper tail when a >= 0); the interpolation three
      // roundings; the quantile 8 ulps of z.
      const bool upper = static_cast<double>(a) >= 0;
      const double side = static_cast<double>(upper ? 1 - pa : pb);
      const double az = std::fabs(static_cast<double>(z)), ends = std::max(std::fabs(static_cast<double>(a)), std::fabs(static_cast<double>(b)));
      const double dz = eps * ((16 + 3 + ends * ends + 1) * side / static_cast<double>(phi(z)) + 8 * az);
      return {d.mean + d.sd * z, d.sd * dz + 2 * eps * (std::fabs(d.mean) + d.sd * az)};
    }
    case Kind::uniform: return {d.min + (big(d.max) - d.min) * U, 3 * eps * (std::fabs(d.min) + std::fabs(d.max))};
    case Kind::triangular: {
      const big w = big(d.max) - d.min, l = big(d.mode) - d.min, r = big(d.max) - d.mode;
      const big x = U * w < l ? d.min + sqrt(U * w * l) : d.max - sqrt((1 - U) * w * r);
      // Three differences and two products round (relative 5 eps under the root, 2.5 out of it), the
      // root and the sum once each.
      return {x, 5 * eps * (std::fabs(d.min) + std::fabs(d.max))};
    }
    case Kind::discrete: break;
  }
  return {0, 0};
}

}  // namespace

TEST_CASE("each continuous distribution's quantile is the 50-digit quantile within its derived bound") {
  const std::vector<Distribution> ds = {
      make(Kind::normal, 11.176, 0.3),          make(Kind::normal, -3, 40),
      make(Kind::lognormal, 0.4, 0.2),          make(Kind::lognormal, 1500, 1.5),
      make(Kind::uniform, 0.05, 0.2),           make(Kind::uniform, -95, 95),
      make(Kind::triangular, 85, 90, 95),       make(Kind::triangular, 0, 0, 1),
      make(Kind::triangular, -2, 1, 1),         make(Kind::truncated_normal, 1500, 60, 1350, 1650),
      make(Kind::truncated_normal, 0, 1, 0.5, 3), make(Kind::truncated_normal, 0, 1, -3, -0.5),
      make(Kind::truncated_normal, 10, 2, 18, 22),  // 4 to 6 sd above the mean
  };
  int checked = 0, failed = 0;
  double worst = 0;  // the largest error as a fraction of its bound
  for (std::size_t k = 0; k < ds.size(); ++k)
    for (std::uint64_t i = 0; i < 500; ++i) {
      const double u = i < 8 ? std::ldexp(1.0, -4 * static_cast<int>(i) - 2) : uniform_open(17, i, static_cast<std::uint32_t>(k));
      const double got = quantile(ds[k], u);
      const Expected e = expected(ds[k], u, got);
      const double err = static_cast<double>(abs(big(got) - e.x));
      const double share = err / e.allowed;
      worst = std::max(worst, share);
      if (share > 1) {
        ++failed;
        UNSCOPED_INFO(kind_name(ds[k].kind) << " #" << k << " at u = " << u << ": " << got << " off by " << err << ", allowed " << e.allowed);
      }
      ++checked;
    }
  INFO("the worst error is " << worst << " of its bound");
  CHECK(checked == 13 * 500);
  CHECK(failed == 0);
}

TEST_CASE("discrete values come at the frequencies of their weights, and every draw finds one") {
  Distribution d;
  d.kind = Kind::discrete;
  d.values = {-0.9, -0.8, -0.7, 0.0};
  d.cumulative = cumulative_weights({0.5, 0.25, 0.25, 0.0});
  CHECK(d.cumulative.back() == 1.0);
  std::vector<int> count(d.values.size(), 0);
  const int n = 100000;
  for (std::uint64_t i = 0; i < static_cast<std::uint64_t>(n); ++i) {
    const double x = quantile(d, uniform_open(19, i, 0));
    for (std::size_t v = 0; v < d.values.size(); ++v) count[v] += x == d.values[v];
  }
  CHECK(count[0] + count[1] + count[2] + count[3] == n);
  CHECK(count[3] == 0);  // weight 0: never drawn
  // Binomial standard errors; 5 of them is a one-in-a-million miss, fixed by the seed.
  CHECK(std::fabs(count[0] - 0.5 * n) < 5 * std::sqrt(0.25 * n));
  CHECK(std::fabs(count[1] - 0.25 * n) < 5 * std::sqrt(0.1875 * n));
  // The ends of (0, 1).
  CHECK(quantile(d, 0x1p-53) == -0.9);
  CHECK(quantile(d, 1 - 0x1p-53) == -0.7);
}

TEST_CASE("the kinds' names are the uncertainty file's") {
  for (const char* name : {"normal", "truncated-normal", "uniform", "triangular", "lognormal", "discrete"}) {
    Kind k{};
    REQUIRE(kind_of(name, k));
    CHECK(kind_name(k) == name);
  }
  Kind k{};
  CHECK_FALSE(kind_of("gaussian", k));
}

}  // namespace check_distribution
