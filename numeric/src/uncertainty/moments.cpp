// Closed-form moments (moments.hpp). Compiled with -ffp-contract=off, as the rest of the sampling.
#include "impact3d/uncertainty/moments.hpp"

#include <cmath>

#include "impact3d/uncertainty/portable_math.hpp"

namespace impact3d::uncertainty {

namespace {

constexpr double kInvSqrt2Pi = 0.398942280401432677939946059934;

double density(double x) { return kInvSqrt2Pi * portable_exp(-0.5 * x * x); }

// A normal truncated to [a, b], in standard units alpha, beta: the mass Z between them taken from the
// nearer tail, so that a window far from the mean keeps its digits.
Moments truncated(double mean, double sd, double a, double b) {
  const double alpha = (a - mean) / sd, beta = (b - mean) / sd;
  const double z = alpha > 0 ? normal_upper_tail(alpha) - normal_upper_tail(beta) : normal_cdf(beta) - normal_cdf(alpha);
  const double pa = density(alpha), pb = density(beta);
  const double shift = (pa - pb) / z;
  const double var = 1 + (alpha * pa - beta * pb) / z - shift * shift;
  return {mean + sd * shift, sd * std::sqrt(var > 0 ? var : 0)};
}

}  // namespace

Moments moments(const Distribution& d) {
  switch (d.kind) {
    case Distribution::Kind::normal:
      return {d.mean, d.sd};
    case Distribution::Kind::truncated_normal:
      return truncated(d.mean, d.sd, d.min, d.max);
    case Distribution::Kind::uniform:
      return {0.5 * (d.min + d.max), (d.max - d.min) / std::sqrt(12.0)};
    case Distribution::Kind::triangular: {
      const double a = d.min, b = d.max, c = d.mode;
      const double var = (a * a + b * b + c * c - a * b - a * c - b * c) / 18;
      return {(a + b + c) / 3, std::sqrt(var > 0 ? var : 0)};
    }
    case Distribution::Kind::lognormal: {
      const double s2 = d.sigma * d.sigma, mean = d.median * portable_exp(0.5 * s2);
      return {mean, mean * std::sqrt(portable_exp(s2) - 1)};
    }
    case Distribution::Kind::discrete: {
      double mean = 0, previous = 0;
      for (std::size_t i = 0; i < d.values.size(); ++i) mean += (d.cumulative[i] - previous) * d.values[i], previous = d.cumulative[i];
      double var = 0;
      previous = 0;
      for (std::size_t i = 0; i < d.values.size(); ++i) {
        const double r = d.values[i] - mean;
        var += (d.cumulative[i] - previous) * r * r, previous = d.cumulative[i];
      }
      return {mean, std::sqrt(var)};
    }
  }
  return {};
}

}  // namespace impact3d::uncertainty
