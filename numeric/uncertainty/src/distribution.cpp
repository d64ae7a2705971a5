// Compiled with -ffp-contract=off, as portable_math.cpp is: the samples must not depend on FMA.
#include "impact3d/uncertainty/distribution.hpp"

#include <algorithm>
#include <cmath>

#include "impact3d/uncertainty/portable_math.hpp"

namespace impact3d::uncertainty {
namespace {

constexpr struct {
  Distribution::Kind kind;
  std::string_view name;
} kNames[] = {{Distribution::Kind::normal, "normal"},         {Distribution::Kind::truncated_normal, "truncated-normal"},
              {Distribution::Kind::uniform, "uniform"},       {Distribution::Kind::triangular, "triangular"},
              {Distribution::Kind::lognormal, "lognormal"}, {Distribution::Kind::discrete, "discrete"}};

}  // namespace

TruncatedWindow truncated_window(const Distribution& d) {
  const double a = (d.min - d.mean) / d.sd, b = (d.max - d.mean) / d.sd;
  if (a < 0 && b > 0) return {false, false, normal_cdf(a), normal_cdf(b), 0, 0};
  // One side of the mean: mirrored to the upper side, the nearer end first.
  const bool lower = b <= 0;
  const double near = lower ? -b : a, far = lower ? -a : b;
  const double mills = normal_mills_ratio(near);
  // Q(far) / Q(near) = e^(-(far - near)(far + near)/2) M(far) / M(near), with no tail formed.
  const double ratio = portable_exp(-0.5 * (far - near) * (far + near)) * normal_mills_ratio(far) / mills;
  return {true, lower, near, far, mills, ratio};
}

namespace {

// The x in [a, b], 0 <= a, with Q(x) = Q(a) (1 - v (1 - ratio)): ln Q(x) - ln Q(a) = T, that is
// h(d) = -d (2a + d)/2 + ln(M(a + d) / M(a)) - T = 0 in d = x - a, which forms no tail. h decreases
// (h' = -1/M) and is concave (M' = xM - 1 < 0), so Newton's steps, after the first (the exponential
// law's d = -T M(a), which lands right of the root), come down to the root monotonically.
double tail_quantile(const TruncatedWindow& w, double v) {
  const double a = w.a, width = w.b - w.a;
  const double T = portable_log((1 - v) + v * w.ratio);  // 1 - v is exact for every draw
  double d = std::min(-T * w.mills, width);
  for (int i = 0; i < 200; ++i) {
    const double x = a + d, m = normal_mills_ratio(x);
    const double h = -0.5 * d * (2 * a + d) + portable_log(m / w.mills) - T;
    const double next = std::clamp(d + h * m, 0.0, width);
    if (!(next < d)) break;  // the descent has stopped: rounding has reached the root
    const bool close = d - next <= 0x1p-53 * x;
    d = next;
    if (close) break;
  }
  return a + d;
}

}  // namespace

double truncated_normal(const Distribution& d, const TruncatedWindow& w, double u) {
  if (w.tail) {
    const double z = w.lower ? -tail_quantile(w, 1 - u) : tail_quantile(w, u);
    return std::clamp(d.mean + d.sd * z, d.min, d.max);
  }
  // Across the mean, [Phi(a), Phi(b)] holds 1/2 and the window's mass is not small: kept inside the
  // draws' own range, [2^-53, 1 - 2^-53], whose resolution no end beyond 8 sd would change.
  auto inside = [](double p) { return std::clamp(p, 0x1p-53, 1 - 0x1p-53); };
  const double z = normal_quantile(inside(w.a + u * (w.b - w.a)));
  return std::clamp(d.mean + d.sd * z, d.min, d.max);
}

std::string_view kind_name(Distribution::Kind k) {
  for (const auto& n : kNames)
    if (n.kind == k) return n.name;
  return {};
}

bool kind_of(std::string_view name, Distribution::Kind& k) {
  for (const auto& n : kNames)
    if (n.name == name) {
      k = n.kind;
      return true;
    }
  return false;
}

double quantile(const Distribution& d, double u) {
  switch (d.kind) {
    case Distribution::Kind::normal: return d.mean + d.sd * normal_quantile(u);
    case Distribution::Kind::truncated_normal: return truncated_normal(d, truncated_window(d), u);
    case Distribution::Kind::uniform: return std::clamp(d.min + (d.max - d.min) * u, d.min, d.max);
    case Distribution::Kind::triangular: {
      const double width = d.max - d.min, left = d.mode - d.min, right = d.max - d.mode;
      const double x = u * width < left ? d.min + std::sqrt(u * width * left) : d.max - std::sqrt((1 - u) * width * right);
      return std::clamp(x, d.min, d.max);
    }
    case Distribution::Kind::lognormal: return d.median * portable_exp(d.sigma * normal_quantile(u));
    case Distribution::Kind::discrete: {
      const auto it = std::upper_bound(d.cumulative.begin(), d.cumulative.end(), u);
      return d.values[static_cast<std::size_t>(std::min<std::ptrdiff_t>(it - d.cumulative.begin(),
                                                                        static_cast<std::ptrdiff_t>(d.values.size()) - 1))];
    }
  }
  return 0;
}

std::vector<double> cumulative_weights(const std::vector<double>& weights) {
  std::vector<double> c(weights.size());
  double total = 0;
  for (const double w : weights) total += w;
  double run = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) c[i] = (run += weights[i]) / total;
  if (!c.empty()) c.back() = 1;
  return c;
}

}  // namespace impact3d::uncertainty
