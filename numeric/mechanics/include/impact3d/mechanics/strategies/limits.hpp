// What the strategies share: the solution plane through n along a contact-plane direction, and the
// flags for ratios that came out non-finite or negative.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "impact3d/scalar/exact.hpp"
#include "impact3d/scalar/planar_norm.hpp"
#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/rounding.hpp"
#include "impact3d/mechanics/strategy.hpp"

namespace impact3d::strategies {

// The size that decides whether a direction is lost in rounding; exact types test for zero alone.
template <typename Scalar>
Scalar magnitude(const Vec3<Scalar>& v) {
  if constexpr (!rounding::tracks_rounding_v<Scalar>) return Scalar(0);
  else return v.norm();
}

// |(a, b)|; exact types take the root only when it is rational.
template <typename Scalar>
Scalar plane_length(const Scalar& a, const Scalar& b) {
  if constexpr (is_exact_v<Scalar>) {
    return exact_sqrt(Scalar(a * a + b * b), "the direction of the solution plane (|(P_t, P_z)| or |(V_rt, V_rz)|)");
  } else {
    return planar_norm(a, b);
  }
}

// The plane through n containing the contact-plane direction (d_t, d_z) of the given length; when that
// direction is lost in rounding (relative to `scale`) the t axis is used and `undefined` is recorded as a
// warning. The plane angle from t towards z is stored in the solution for a report.
template <typename Scalar>
PlaneAxes<Scalar> solution_plane(const Problem<Scalar>& p, const Scalar& d_t, const Scalar& d_z, const Scalar& length,
                                 const Scalar& scale, ImpulseSolution<Scalar>& out, const char* undefined) {
  PlaneAxes<Scalar> ax{Scalar(1), Scalar(0)};
  const DecisionName<Scalar> name(decision_names::plane_direction);
  if (p.negligible(length, scale))
    out.warn(WarningCode::plane_undefined, [&] { return undefined; });
  else
    ax = {Scalar(d_t / length), Scalar(d_z / length)};
  out.plane = ax;
  if constexpr (!is_exact_v<Scalar>) {  // an angle is not rational; the exact report takes it at 100 digits
    using std::atan2;
    if (out.for_report) out.plane_angle_deg = degrees(Scalar(atan2(ax.s, ax.c)));
  }
  return ax;
}

template <typename Scalar>
void flag_if_not_finite(ImpulseSolution<Scalar>& out, const Scalar& value, const char* name) {
  if (!is_finite(value))
    out.warn(WarningCode::non_physical_limit, [&] {
      return std::string(name) + " is undefined: the normal impulse of the solution that defines it is zero";
    });
}

// A regime decided by mu >= limit is undecided when mu lies within the limit's rounding bound
// (rounding.hpp, with the quotient's factor): a wider precision could take the other branch. The impulse
// is continuous across the threshold, so the warning says which decision is in doubt, not that the
// numbers are.
template <typename Scalar>
void flag_if_undecided(ImpulseSolution<Scalar>& out, const Problem<Scalar>& p, const Scalar& mu, const Scalar& limit,
                       const char* name) {
  // An enclosure decides for itself: its comparisons record what they cannot decide (decisions.hpp).
  if constexpr (rounding::tracks_rounding_v<Scalar>) {
    using std::abs;
    if (!is_finite(limit)) return;
    auto bound = [&](const Scalar& amplification) {
      return Scalar(rounding::relative_bound(amplification) * p.quotient * (Scalar(1) + abs(limit)));
    };
    if (p.within(Scalar(mu - limit), bound, false))
      out.warn(WarningCode::undecided, [&] {
        std::ostringstream text;
        text.precision(3);
        text << "undecided: mu = " << to_double(mu) << " lies within the rounding bound ("
             << to_double(bound(p.amplification)) << ") of " << name << " = " << to_double(limit)
             << "; a wider precision may take the other regime";
        return text.str();
      });
  }
}

template <typename Scalar>
void flag_if_negative_ratio(ImpulseSolution<Scalar>& out, const Scalar& mu, const char* name) {
  const DecisionName<Scalar> decision(decision_names::ratio_sign);
  if (mu < Scalar(0))
    out.warn(WarningCode::negative_ratio, [&] {
      return std::string(name) + " used is negative: the contact-plane impulse acts along the initial sliding";
    });
}

}  // namespace impact3d::strategies
