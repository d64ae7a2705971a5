// What a Monte Carlo run reports of one output: mean, standard deviation and percentiles, each with its
// Monte Carlo standard error. Everything is computed with +, -, *, / and sqrt only, from the values in
// the order given (the moments) and their order statistics (the percentiles), so the same values in
// the same order give the same bits on every platform.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace impact3d::uncertainty {

// The percentiles reported (many-cases.md, issue 12), in percent.
inline constexpr std::array<double, 9> kPercentiles{1, 2.5, 5, 25, 50, 75, 95, 97.5, 99};
// Their keys in the JSON output, as the contract spells them.
inline constexpr std::array<const char*, 9> kPercentileKeys{"1", "2.5", "5", "25", "50", "75", "95", "97.5", "99"};

struct Summary {
  std::size_t count = 0;  // the values summarized
  double mean = 0, mean_se = 0;  // se: sd / sqrt(count)
  double sd = 0;                 // with count - 1 in the denominator; 0 for one value
  double min = 0, max = 0;
  std::array<double, 9> percentile{}, percentile_se{};
};

// Type 7 of Hyndman and Fan (R's and NumPy's default): x[h] interpolated linearly at h = (n - 1) p,
// 0-based, for p in [0, 1] of the sorted values (not empty), or of values whose order statistics at
// the two positions it reads stand in place.
double percentile_type7(const std::vector<double>& sorted, double p);

// The values' summary (they are overwritten: the order statistics it reads are selected, not sorted;
// none may be NaN or infinite; empty gives count 0).
// A percentile's standard error is the quantile function's slope times the binomial standard error of
// its probability: (Q(p + s) - Q(p - s)) / 2 with s = sqrt(p (1 - p) / n), the two probabilities kept
// in [0, 1] (and the difference scaled to the width kept). It needs no density estimate and no
// assumption of normality.
Summary summarize(std::vector<double>& values);

// The same for angles in degrees that wrap at +-180: the values are unwrapped at the widest empty arc
// between them, so that a spread across +-180 (or across 0 and 360) is one interval, summarized as
// above, and the mean, min, max and percentiles are wrapped back into (-180, 180], or [0, 360) when
// `from_zero` (PDOF's range). Values outside [-360, 360] are refused (std::invalid_argument): they are
// not angles of a result. No trigonometry: nothing that differs between platforms' libraries.
Summary summarize_angle_deg(std::vector<double>& values, bool from_zero = false);

}  // namespace impact3d::uncertainty
