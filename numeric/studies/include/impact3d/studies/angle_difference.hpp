// The difference of two angles in degrees on the circle, for outputs that wrap (monte_carlo_outputs()'s
// `angle`): the first-order propagation of a Monte Carlo run and a reconstruction's residuals.
#pragma once

#include <cmath>

namespace impact3d::studies {

// a - b, in [-180, 180).
inline double angle_difference(double a, double b) {
  const double d = std::fmod(a - b, 360.0);
  return d >= 180 ? d - 360 : d < -180 ? d + 360 : d;
}

}  // namespace impact3d::studies
