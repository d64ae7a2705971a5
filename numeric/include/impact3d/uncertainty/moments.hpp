// The mean and standard deviation of each distribution an uncertainty file gives (distribution.hpp),
// in closed form, for the first-order (linearized) propagation beside Monte Carlo. Built from
// portable_math.hpp's exp and normal CDF and IEEE-rounded arithmetic: the same bits on every platform.
#pragma once

#include "impact3d/uncertainty/distribution.hpp"

namespace impact3d::uncertainty {

struct Moments {
  double mean = 0, sd = 0;
};

// For a distribution whose parameters are valid (the reader's checks).
Moments moments(const Distribution& d);

}  // namespace impact3d::uncertainty
