// The mean and standard deviation of each distribution an uncertainty file gives (distribution.hpp),
// in closed form, for the first-order (linearized) propagation beside Monte Carlo. Built from
// portable_math.hpp's exp and normal CDF and IEEE-rounded arithmetic: the same bits on every platform.
#pragma once

#include <string>

#include "impact3d/uncertainty/distribution.hpp"

namespace impact3d::uncertainty {

struct Moments {
  double mean = 0, sd = 0;
};

// For a distribution whose parameters are valid (the reader's checks).
Moments moments(const Distribution& d);

// Why a truncated normal's samples would not resolve its law to double precision, or empty: its sd is
// below 2^-32 of the values it takes (their magnitude, their distance from the normal's mean) or of
// the normal's sd (the standardized draw resolves about eps of one sd near the mean), so that fewer
// than 2^20 resolvable values would lie across one sd. Beyond that, the sampler keeps its digits any
// number of sd out (distribution.hpp); this bounds a window's distance out to about 2^16 sd, and its
// width to about 2^-30 of its values and of the normal's sd.
std::string truncated_sampling_problem(const Distribution& d);

}  // namespace impact3d::uncertainty
