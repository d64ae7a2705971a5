// Whether a solution's precision can deliver it: a NaN or an infinity, or a rounding bound beyond the
// trusted fraction (rounding.hpp), becomes a warning naming the quantity and the precision that
// resolves it, so that no result is printed as if fine when it is not.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "impact3d/scalar/planar_norm.hpp"
#include "impact3d/mechanics/post_impact.hpp"
#include "impact3d/mechanics/rounding.hpp"

namespace impact3d {

template <typename Scalar>
bool solution_finite(const Solution<Scalar>& s) {
  const auto& i = s.impulse;
  for (const auto* o : {&i.mu, &i.mu_t, &i.mu_z, &i.plane_angle_deg, &s.swerve_deg, &s.swerve_speed})
    if (*o && !is_finite(**o)) return false;
  bool ok = all_finite(i.P_C) && all_finite(s.P_W) && all_finite(s.V_rf) && is_finite(s.sliding_after) &&
            is_finite(s.restitution_effective) && is_finite(s.energy_before) && is_finite(s.energy_after) &&
            is_finite(s.energy_loss);
  for (int k = 0; k < 2; ++k)
    ok = ok && all_finite(s.after[k].v_W) && all_finite(s.after[k].w_B) && is_finite(s.change[k].dv) &&
         (!s.change[k].pdof_deg || is_finite(*s.change[k].pdof_deg));
  return ok;
}

// The relative rounding bound of a solution: kResultRoundings eps A (1 + |V_cp / V_n|), the last factor
// given as `quotient`.
template <typename Scalar>
Scalar rounding_bound_of(const Scalar& amplification, const Scalar& quotient) {
  return rounding::relative_bound(Scalar(amplification * quotient));
}

// Whether a rounding bound is within the trusted fraction (a NaN is not).
template <typename Scalar>
bool trusted(const Scalar& bound) {
  return to_double(bound) <= rounding::kTrustedFraction;
}

// An enclosure's width: the largest radius of the impulse's components over the impulse's size (the
// ratios and states follow from it), infinite where any of them is not finite.
template <typename Scalar>
Scalar relative_radius(const Vec3<Scalar>& P) {
  Scalar size(0), widest(0);
  for (int k = 0; k < 3; ++k) {
    if (!P[k].finite()) return std::numeric_limits<Scalar>::infinity();
    size = Scalar::hull(size, abs(P[k].midpoint())).upper();
    widest = Scalar::hull(widest, P[k].radius()).upper();
  }
  if (size == Scalar(0)) return widest == Scalar(0) ? Scalar(0) : std::numeric_limits<Scalar>::infinity();
  return Scalar(widest / size).upper();
}

// An enclosure states its own width (issue 14): a wide one is flagged with the conditions that widen it,
// the condition of K and the approach's obliquity |V_cp / V_n| (a near-grazing contact).
template <typename Scalar>
void flag_width(Solution<Scalar>& s, const Scalar& kappa) {
  s.rounding_bound = relative_radius(s.impulse.P_C);
  if (s.rounding_bound.finite() && to_double(s.rounding_bound) <= rounding::kTrustedFraction) return;
  const Scalar obliquity = planar_norm(s.V_ri.y(), s.V_ri.z()) / s.V_ri.x();
  std::ostringstream text;
  text.precision(3);
  text << "wide enclosure: the impulse is certified only to a relative radius of " << to_double(s.rounding_bound)
       << " at " << EnclosureTraits<Scalar>::bits() << " bits; its conditions: kappa(K) = " << to_double(kappa)
       << ", |V_cp / V_n| = " << to_double(obliquity)
       << " (an ill-conditioned K or a near-grazing contact widens every enclosure); more bits narrow it";
  s.warnings.push_back({WarningCode::rounding, text.str()});
}

// `amplification`: the problem's (rounding.hpp). Ratios carry their quotient's factor 1 + |V_cp / V_n|
// besides, so the check uses the larger of the two. `kappa`: the condition of K, which an enclosure's
// warning names.
template <typename Scalar>
void flag_precision(Solution<Scalar>& s, const Scalar& amplification, const Scalar& kappa) {
  if constexpr (is_enclosure_v<Scalar>) {
    if (!solution_finite(s))
      s.warnings.push_back({WarningCode::not_finite,
                            "not finite: an enclosure is unbounded (printed as null in JSON); it certifies nothing"});
    flag_width(s, kappa);
  } else if constexpr (!is_exact_v<Scalar>) {
    (void)kappa;
    if (!solution_finite(s))
      s.warnings.push_back({WarningCode::not_finite,
                            "not finite: a result is NaN or infinite at this precision (printed as null in JSON); "
                            "it cannot be trusted"});
    const Scalar quotient = rounding::quotient_factor(s.V_ri);
    s.rounding_bound = rounding_bound_of(amplification, quotient);
    // An integrated impulse (stronge) adds its integration's error to the rounding.
    const Scalar integration = s.impulse.integration_error ? *s.impulse.integration_error : Scalar(0);
    s.rounding_bound += integration;
    const double a = to_double(Scalar(amplification * quotient));
    const double bound = to_double(s.rounding_bound);
    if (trusted(s.rounding_bound)) return;
    std::ostringstream text;
    text.precision(2);
    text << "rounding: the impulse, its ratios and everything computed from them may be off by up to " << bound
         << " of their size at this precision (" << rounding::kResultRoundings
         << " eps kappa(K) cond(J) (|v_IC1|+|v_IC2|)/V_rn (1+|V_cp/V_n|) = " << a
         << "), beyond the trusted " << rounding::kTrustedFraction << "; ";
    const std::string wider = rounding::precision_for(a);
    if (!trusted(integration))
      text << "the integration's error bound is " << to_double(integration)
           << " of it (the steps' truncation, its events and the last of a slide to rest): --precision 50 narrows it";
    else if (!std::isfinite(a))
      text << "K or an inertia tensor is not positive definite at this precision: solve with --precision 100";
    else if (wider.empty())
      text << "no precision of impact3d resolves it";
    else
      text << "--precision " << wider << " resolves it";
    s.warnings.push_back({WarningCode::rounding, text.str()});
  }
}

}  // namespace impact3d
