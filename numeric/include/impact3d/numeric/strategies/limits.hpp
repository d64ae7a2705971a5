// What the strategies share: the solution plane through n along a contact-plane direction, and the
// flags for ratios that came out non-finite or negative.
#pragma once

#include <cmath>
#include <string>

#include "impact3d/numeric/problem.hpp"
#include "impact3d/numeric/strategy.hpp"

namespace impact3d::strategies {

// The plane through n containing the contact-plane direction (d_t, d_z); when that direction is lost in
// rounding (relative to `scale`) the t axis is used and `undefined` is recorded as a warning. The plane
// angle from t towards z is stored in the solution.
template <typename Scalar>
PlaneAxes<Scalar> solution_plane(const Problem<Scalar>& p, const Scalar& d_t, const Scalar& d_z, const Scalar& scale,
                                 ImpulseSolution<Scalar>& out, const std::string& undefined) {
  using std::atan2;
  using std::hypot;
  const Scalar length = hypot(d_t, d_z);
  PlaneAxes<Scalar> ax{Scalar(1), Scalar(0)};
  if (p.negligible(length, scale))
    out.warnings.push_back({WarningCode::plane_undefined, undefined});
  else
    ax = {Scalar(d_t / length), Scalar(d_z / length)};
  out.plane_angle_deg = atan2(ax.s, ax.c) * Scalar(180) / pi<Scalar>();
  return ax;
}

template <typename Scalar>
void flag_if_not_finite(ImpulseSolution<Scalar>& out, const Scalar& value, const std::string& name) {
  using std::isfinite;
  if (!isfinite(value))
    out.warnings.push_back({WarningCode::non_physical_limit,
                            name + " is undefined: the normal impulse of the solution that defines it is zero"});
}

template <typename Scalar>
void flag_if_negative_ratio(ImpulseSolution<Scalar>& out, const Scalar& mu, const std::string& name) {
  if (mu < Scalar(0))
    out.warnings.push_back({WarningCode::negative_ratio,
                            name + " used is negative: the contact-plane impulse acts along the initial sliding"});
}

}  // namespace impact3d::strategies
