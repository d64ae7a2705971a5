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
// inverts Phi over [Phi(a), Phi(b)], in the upper tail when the window is above the mean so that no
// probability near 1 is formed; the result is clamped to [min, max] against rounding.
double quantile(const Distribution& d, double u);

// What a truncated normal's quantile inverts over: [Phi(a), Phi(b)] for the standardized ends a, b, or,
// when the window is above the mean (upper), the upper tails [Q(a), Q(b)]. It depends on the
// distribution alone, so a sampler computes it once; truncated_normal(d, truncated_window(d), u) is
// quantile(d, u).
struct TruncatedWindow {
  bool upper;
  double a, b;
};
TruncatedWindow truncated_window(const Distribution& d);
double truncated_normal(const Distribution& d, const TruncatedWindow& w, double u);

// The cumulative weights of a discrete distribution: running sums divided by the total, the last set
// to exactly 1 so that every u < 1 finds a value.
std::vector<double> cumulative_weights(const std::vector<double>& weights);

}  // namespace impact3d::uncertainty
