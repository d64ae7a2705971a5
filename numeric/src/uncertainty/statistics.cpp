#include "impact3d/uncertainty/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impact3d::uncertainty {

namespace {

// Neumaier's compensated sum, in the order given: the result does not depend on how the samples were
// split over threads because the values arrive sorted.
class Sum {
 public:
  void add(double x) {
    const double t = s_ + x;
    c_ += std::fabs(s_) >= std::fabs(x) ? (s_ - t) + x : (x - t) + s_;
    s_ = t;
  }
  double value() const { return s_ + c_; }

 private:
  double s_ = 0, c_ = 0;
};

Summary summarize_sorted(const std::vector<double>& x) {
  Summary s;
  s.count = x.size();
  if (x.empty()) return s;
  const double n = static_cast<double>(x.size());
  Sum sum;
  for (double v : x) sum.add(v);
  s.mean = sum.value() / n;
  // Two passes: the squares of deviations, not the difference of two large sums.
  Sum squares;
  for (double v : x) squares.add((v - s.mean) * (v - s.mean));
  s.sd = x.size() > 1 ? std::sqrt(squares.value() / (n - 1)) : 0.0;
  s.mean_se = s.sd / std::sqrt(n);
  s.min = x.front();
  s.max = x.back();
  for (std::size_t k = 0; k < kPercentiles.size(); ++k) {
    const double p = kPercentiles[k] / 100;
    s.percentile[k] = percentile_type7(x, p);
    const double half = std::sqrt(p * (1 - p) / n);
    const double lo = std::max(0.0, p - half), hi = std::min(1.0, p + half);
    s.percentile_se[k] = hi > lo ? (percentile_type7(x, hi) - percentile_type7(x, lo)) * (half / (hi - lo)) : 0.0;
  }
  return s;
}

// Into (-180, 180]: x is in (-540, 540], so one step of 360 at most.
double wrap_deg(double x) {
  if (x > 180) return x - 360;
  if (x <= -180) return x + 360;
  return x;
}

}  // namespace

double percentile_type7(const std::vector<double>& sorted, double p) {
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const auto i = static_cast<std::size_t>(std::floor(h));
  if (i + 1 >= sorted.size()) return sorted.back();
  const double f = h - static_cast<double>(i);
  // x_i + f (x_{i+1} - x_i), exact at f = 0 and equal to x_{i+1} at f = 1 only up to rounding: the
  // difference form keeps the result inside [x_i, x_{i+1}].
  return sorted[i] + f * (sorted[i + 1] - sorted[i]);
}

Summary summarize(std::vector<double>& values) {
  std::sort(values.begin(), values.end());
  return summarize_sorted(values);
}

Summary summarize_angle_deg(std::vector<double>& values, bool from_zero) {
  for (double v : values)
    if (!(v >= -360 && v <= 360)) throw std::invalid_argument("an angle outside [-360, 360] degrees");
  for (double& v : values) v = wrap_deg(v);
  std::sort(values.begin(), values.end());
  if (values.size() < 2) {
    if (from_zero)
      for (double& v : values) v = v < 0 ? v + 360 : v;
    return summarize_sorted(values);
  }
  // The widest gap: between neighbours, or the one across +-180 (from the last to the first).
  const std::size_t n = values.size();
  std::size_t cut = n;  // the first value of the unwrapped run; n: the gap across +-180 is widest
  double widest = values.front() + 360 - values.back();
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (values[i + 1] - values[i] > widest) widest = values[i + 1] - values[i], cut = i + 1;
  if (cut < n) {
    std::rotate(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(cut), values.end());
    for (std::size_t i = n - cut; i < n; ++i) values[i] += 360;  // those below the gap, now after it
  }
  Summary s = summarize_sorted(values);
  const auto back = [from_zero](double x) {
    x = wrap_deg(x);
    return from_zero && x < 0 ? x + 360 : x;
  };
  s.mean = back(s.mean);
  s.min = back(s.min);
  s.max = back(s.max);
  for (double& p : s.percentile) p = back(p);
  return s;
}

}  // namespace impact3d::uncertainty
