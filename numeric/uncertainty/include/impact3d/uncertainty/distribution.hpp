// The distributions an uncertainty file gives an input (many-cases.md, "montecarlo"), each as its
// quantile function: the value at probability u in (0, 1). Sampling is then one uniform draw per input
// (philox.hpp), or a normal score from the Gaussian copula mapped back to u, and the same draw gives the
// same value on every platform (portable_math.hpp).
#pragma once

#include <string_view>
#include <vector>

namespace impact3d::uncertainty {

struct Distribution {
  enum class Kind { normal, truncated_normal, uniform, triangular, lognormal, discrete } kind = Kind::normal;
  // By kind, in the case's units: normal (mean, sd); truncated-normal (mean, sd, min, max); uniform
  // (min, max); triangular (min, mode, max); lognormal (median, sigma of the logarithm); discrete
  // (values, not empty, and cumulative: the running sums of the weights divided by their total, the
  // last exactly 1).
  double mean = 0, sd = 0, min = 0, max = 0, mode = 0, median = 0, sigma = 0;
  std::vector<double> values, cumulative;
};

// The spelling of each kind in an uncertainty file, and back; false for a name that is none.
std::string_view kind_name(Distribution::Kind k);
bool kind_of(std::string_view name, Distribution::Kind& k);

// The quantile at u in (0, 1), for a distribution whose parameters are valid (the reader's checks:
// sd, sigma > 0, min < max, min <= mode <= max, weights >= 0 with a positive sum). A truncated normal
// across its mean inverts Phi over [Phi(a), Phi(b)]; one wholly on one side of its mean is inverted from
// its nearer end in logarithms of Mills' ratio (portable_math.hpp), so that a window any number of sd
// out keeps its digits where its tail probabilities are below the smallest double. The result is
// clamped to [min, max] against rounding.
double quantile(const Distribution& d, double u);

// What a truncated normal's quantile inverts over, computed once per distribution:
// truncated_normal(d, truncated_window(d), u) is quantile(d, u). Across the mean (tail false): a, b are
// Phi of the standardized ends. On one side (tail): a <= b the standardized ends mirrored to the upper
// side (lower: the window is below the mean), mills M(a) and ratio Q(b) / Q(a).
struct TruncatedWindow {
  bool tail, lower;
  double a, b, mills, ratio;
};
TruncatedWindow truncated_window(const Distribution& d);
double truncated_normal(const Distribution& d, const TruncatedWindow& w, double u);

// The cumulative weights of a discrete distribution: running sums divided by the total, the last set
// to exactly 1 so that every u < 1 finds a value.
std::vector<double> cumulative_weights(const std::vector<double>& weights);

}  // namespace impact3d::uncertainty
