// Closed-form moments (moments.hpp). Compiled with -ffp-contract=off, as the rest of the sampling.
#include "impact3d/uncertainty/moments.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "impact3d/uncertainty/portable_math.hpp"

namespace impact3d::uncertainty {

namespace {

constexpr double kInvSqrt2Pi = 0.398942280401432677939946059934;

double density(double x) { return kInvSqrt2Pi * portable_exp(-0.5 * x * x); }

// The mean and sd of d in [0, width] under the weight e^(-d (2a + d)/2), a >= 0: a normal's window on
// one side of its mean, standardized, mirrored to the upper side and taken from its nearer end a, as
// its density over phi(a). By composite 8-point Gauss-Legendre quadrature, central moments taken about
// the mean found first: closed forms there subtract nearly equal numbers (1 - rho and M(a) - rho M(b)
// in a narrow window, 1 - shift (shift - a) far out) and lost up to 1e-5 of the sd. Panels of
// 1 / (a + 1), the weight's scale, to where it is below e^-44 of its start; at most 64 of them.
struct TailMoments {
  double mass, mean, sd;  // the weight's integral, and d's mean and sd under it
};

TailMoments tail_window(double a, double width) {
  static constexpr double node[4] = {0.18343464249564980494, 0.52553240991632898582, 0.79666647741362673959,
                                     0.96028985649753623168};
  static constexpr double weight[4] = {0.36268378337836198297, 0.31370664587788728734, 0.22238103445337447054,
                                       0.10122853629037625915};
  const double top = std::fmin(width, 45 / (a + 1));
  const double panels = std::fmin(64, std::ceil(top * (a + 1)));
  const double h = top / panels;
  auto integral = [&](auto f) {
    double sum = 0;
    for (double p = 0; p < panels; ++p) {
      const double centre = (p + 0.5) * h;
      for (int k = 0; k < 4; ++k)
        for (const double side : {-1.0, 1.0}) {
          const double d = centre + side * node[k] * 0.5 * h;
          sum += weight[k] * f(d) * portable_exp(-0.5 * d * (2 * a + d));
        }
    }
    return sum;
  };
  const double m0 = integral([](double) { return 1.0; });
  const double centre = integral([](double d) { return d; }) / m0;
  const double var = integral([&](double d) { return (d - centre) * (d - centre); }) / m0;
  return {0.5 * h * m0, centre, std::sqrt(var)};
}

// A normal truncated to [a, b], in standard units alpha, beta. Across the mean, the mass Z between
// them taken from the nearer tail; on one side, tail_window.
Moments truncated(double mean, double sd, double a, double b) {
  const double alpha = (a - mean) / sd, beta = (b - mean) / sd;
  if (alpha < 0 && beta > 0 && beta - alpha < 0.5) {
    // Narrow across the mean: the closed form's variance, about w^2/12 from terms of size 1, cancels.
    // Each side of the mean by tail_window (both from 0, so their masses compare), then mixed.
    const TailMoments lo = tail_window(0, -alpha), hi = tail_window(0, beta);
    const double total = lo.mass + hi.mass;
    const double shift = (hi.mass * hi.mean - lo.mass * lo.mean) / total;
    const auto spread = [&](const TailMoments& t, double centre) {
      return t.sd * t.sd + (centre - shift) * (centre - shift);
    };
    const double var = (lo.mass * spread(lo, -lo.mean) + hi.mass * spread(hi, hi.mean)) / total;
    return {mean + sd * shift, sd * std::sqrt(var)};
  }
  if (alpha < 0 && beta > 0) {
    const double z = normal_cdf(beta) - normal_cdf(alpha);
    const double pa = density(alpha), pb = density(beta);
    const double shift = (pa - pb) / z;
    const double var = 1 + (alpha * pa - beta * pb) / z - shift * shift;
    return {mean + sd * shift, sd * std::sqrt(var > 0 ? var : 0)};
  }
  const bool lower = beta <= 0;
  const double near = lower ? -beta : alpha, far = lower ? -alpha : beta;
  if (!std::isfinite(near) || !(far > near)) return {std::numeric_limits<double>::quiet_NaN(), 0};
  const TailMoments m = tail_window(near, far - near);
  const double shift = near + m.mean;
  return {mean + sd * (lower ? -shift : shift), sd * m.sd};
}

}  // namespace

std::string truncated_sampling_problem(const Distribution& d) {
  const Moments m = truncated(d.mean, d.sd, d.min, d.max);
  // The sampler resolves about one double of the values, and of the standardized draw about eps
  // of one sd near the mean (a probability near 1/2, or a tail's logarithm near 0).
  const double at = std::fmax(std::fmax(std::fabs(m.mean), std::fabs(m.mean - d.mean)), d.sd);
  if (!std::isfinite(m.mean) || !std::isfinite(m.sd) || !(m.sd >= 0x1p-32 * at))
    return "its window is too narrow, or too far from the mean, to be sampled to double precision: the truncated law's sd "
           "must be at least 2^-32 of its mean's magnitude, of the mean's distance from the normal's mean and of the "
           "normal's sd (2^20 resolvable values across one sd)";
  return {};
}

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
