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
  // Both ends above the mean: upper tails, Q(a) >= Q(b), so nothing rounds near 1.
  if (a >= 0) return {true, normal_upper_tail(a), normal_upper_tail(b)};
  return {false, normal_cdf(a), normal_cdf(b)};
}

double truncated_normal(const Distribution& d, const TruncatedWindow& w, double u) {
  // The probability is kept inside the uniform draws' own range, [2^-53, 1 - 2^-53]: where an end's
  // probability rounds to 0 or 1 (an end beyond 8 sd), the quantile then stays finite.
  auto inside = [](double p) { return std::clamp(p, 0x1p-53, 1 - 0x1p-53); };
  const double z = w.upper ? -normal_quantile(inside(w.a - u * (w.a - w.b))) : normal_quantile(inside(w.a + u * (w.b - w.a)));
  return std::clamp(d.mean + d.sd * z, d.min, d.max);
}

namespace {
}  // namespace

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
