// The Monte Carlo summary's known answers (uncertainty/statistics.hpp), each derived by hand:
// percentiles of 1..10 as R's quantile(1:10, type = 7) gives them, the mean and standard deviation of
// small sets, angles summarized across the wrap, and the percentiles' standard errors on an evenly
// spread sample, where the quantile function's slope is known exactly.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "impact3d/uncertainty/statistics.hpp"

namespace exam_statistics {

using namespace impact3d::uncertainty;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// a and b within k units of epsilon relative to the larger of |b| and 1 (the values here are O(1..100)).
bool near(double a, double b, double k) { return std::fabs(a - b) <= k * kEps * std::max(1.0, std::fabs(b)); }

}  // namespace

TEST_CASE("percentiles of 1..10 are R's type 7: x[h] + f (x[h+1] - x[h]) at h = 9 p") {
  std::vector<double> x = {7, 3, 10, 1, 5, 2, 9, 4, 8, 6};  // unsorted: summarize sorts
  const Summary s = summarize(x);
  // h = 9 p: 0.09, 0.225, 0.45, 2.25, 4.5, 6.75, 8.55, 8.775, 8.91, so 1 + h.
  const std::array<double, 9> expected{1.09, 1.225, 1.45, 3.25, 5.5, 7.75, 9.55, 9.775, 9.91};
  for (std::size_t k = 0; k < expected.size(); ++k) {
    INFO("percentile " << kPercentileKeys[k]);
    // One rounding of h = 9 p and one of the interpolation: 4 eps of the value.
    CHECK(near(s.percentile[k], expected[k], 4));
  }
  CHECK(s.count == 10);
  CHECK(s.mean == 5.5);                               // 55 / 10, exact
  CHECK(near(s.sd, std::sqrt(82.5 / 9), 2));          // sum (i - 5.5)^2 = 82.5, over n - 1
  CHECK(near(s.mean_se, std::sqrt(82.5 / 9) / std::sqrt(10.0), 4));
  CHECK(s.min == 1);
  CHECK(s.max == 10);
}

TEST_CASE("one value: its own mean and percentiles, no spread") {
  std::vector<double> x = {2.5};
  const Summary s = summarize(x);
  CHECK(s.mean == 2.5);
  CHECK(s.sd == 0);
  for (double p : s.percentile) CHECK(p == 2.5);
  for (double se : s.percentile_se) CHECK(se == 0);
  std::vector<double> none;
  CHECK(summarize(none).count == 0);
}

TEST_CASE("angles across +-180 are one interval, wrapped back") {
  // 170, 179, -179, -170: unwrapped at the widest gap (from -170 round to 170, 340 degrees) to
  // 170, 179, 181, 190: mean 180, sd sqrt((100 + 1 + 1 + 100) / 3).
  std::vector<double> x = {179, -170, 170, -179};
  const Summary s = summarize_angle_deg(x);
  CHECK(s.mean == 180);
  CHECK(near(s.sd, std::sqrt(202.0 / 3), 2));
  CHECK(s.min == 170);
  CHECK(s.max == -170);  // 190, wrapped
  CHECK(near(s.percentile[4], 180, 2));  // the median, between 179 and 181
  // PDOF's range [0, 360): 350, 355, 5, 10 are -10, -5, 5, 10 about 0: mean 0, median 0.
  std::vector<double> pdof = {5, 350, 10, 355};
  const Summary p = summarize_angle_deg(pdof, true);
  CHECK(p.mean == 0);
  CHECK(p.min == 350);
  CHECK(p.max == 10);
  CHECK(near(p.sd, std::sqrt(250.0 / 3), 2));
  CHECK(p.percentile[0] >= 350);  // 1 %: -9.85, wrapped into [0, 360)
  CHECK(near(p.percentile[0], 350.15, 64));  // -10 + 0.03 * 5, then + 360: rounding of 360's scale
  // Angles on one side of the wrap are left as they are.
  std::vector<double> plain = {10, 20, 30};
  CHECK(summarize_angle_deg(plain).mean == 20);
  std::vector<double> bad = {400};
  CHECK_THROWS_AS(summarize_angle_deg(bad), std::invalid_argument);
}

TEST_CASE("a percentile's standard error is the quantile slope times sqrt(p (1 - p) / n)") {
  // x_i = i / (n - 1), i = 0..n-1: Q(q) = q exactly at every q (type 7 interpolates linearly between
  // points on the line), so the error is s = sqrt(p (1 - p) / n) itself, where p +- s stays in [0, 1].
  const std::size_t n = 10001;
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = static_cast<double>(i) / static_cast<double>(n - 1);
  const Summary s = summarize(x);
  std::size_t checked = 0;
  for (std::size_t k = 0; k < kPercentiles.size(); ++k) {
    const double p = kPercentiles[k] / 100;
    INFO("percentile " << kPercentileKeys[k]);
    CHECK(std::fabs(s.percentile[k] - p) <= 4 * kEps);
    // Differences of two O(1) values each rounded once, scaled by ~1: 16 eps absolute, relative to an
    // error of ~1e-3 that is 2e-12 -- the check is on the formula, not on the last bits.
    CHECK(std::fabs(s.percentile_se[k] - std::sqrt(p * (1 - p) / n)) <= 16 * kEps);
    ++checked;
  }
  CHECK(checked == 9);
  // The mean of a symmetric grid is its centre; sd sqrt(n (n + 1) / (12 (n - 1)^2)) exactly for i / (n - 1).
  CHECK(std::fabs(s.mean - 0.5) <= 4 * kEps);
  const double nn = static_cast<double>(n);
  CHECK(near(s.sd, std::sqrt(nn * (nn + 1) / (12 * (nn - 1) * (nn - 1))), 64));
}

TEST_CASE("the percentiles read from selected order statistics are those of the sorted values") {
  // Seeded values with many ties (rounded to a coarse grid) and without, at sizes around the edges of
  // the positions read and beyond the size where values are first counted into bins; and shapes that
  // put most values in one bin (an outlier far out: the bins are split again), or all in one value.
  std::uint64_t state = 12345;
  auto next = [&] {  // splitmix64
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1p-53;
  };
  enum Shape { spread, ties, outlier, outliers_both, constant, nested };
  int checked = 0;
  for (std::size_t n : {1u, 2u, 3u, 7u, 100u, 101u, 4999u, 20000u, 300001u})
    for (Shape shape : {spread, ties, outlier, outliers_both, constant, nested}) {
      std::vector<double> x(n);
      for (double& v : x) {
        const double u = next();
        switch (shape) {
          case spread: v = u * 100 - 50; break;
          case ties: v = std::floor(u * 10); break;
          case outlier: v = u; break;
          case outliers_both: v = u * 1e-3; break;
          case constant: v = 2.5; break;
          case nested: v = std::pow(u, 40.0); break;  // most values within 1e-12 of 0: bins within bins
        }
      }
      if (shape == outlier) x[n / 2] = 1e12;
      if (shape == outliers_both) x[0] = -1e300, x[n - 1] = 1e300;
      std::vector<double> sorted = x;
      std::sort(sorted.begin(), sorted.end());
      std::vector<double> work = x;
      const Summary s = summarize(work);
      INFO("n " << n << ", shape " << static_cast<int>(shape));
      CHECK(s.min == sorted.front());
      CHECK(s.max == sorted.back());
      for (std::size_t k = 0; k < kPercentiles.size(); ++k) {
        const double p = kPercentiles[k] / 100;
        CHECK(s.percentile[k] == percentile_type7(sorted, p));  // the same two values, the same arithmetic
        const double half = std::sqrt(p * (1 - p) / static_cast<double>(n));
        const double lo = std::max(0.0, p - half), hi = std::min(1.0, p + half);
        const double se = hi > lo ? (percentile_type7(sorted, hi) - percentile_type7(sorted, lo)) * (half / (hi - lo)) : 0.0;
        CHECK(s.percentile_se[k] == se);
      }
      ++checked;
    }
  CHECK(checked == 9 * 6);
}

}  // namespace exam_statistics
