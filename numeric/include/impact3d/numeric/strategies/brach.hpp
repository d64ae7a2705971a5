// Brach: independent impulse ratios P_t = mu_t P_n, P_z = mu_z P_n (eqs 23-24); a ratio given as
// "critical" is replaced by the condition that sliding along its axis stops (eqs 25-26, both: eq 27).
// The critical ratio of each axis, given the other ratio as used, is reported as a limit.
#pragma once

#include "impact3d/numeric/problem.hpp"
#include "impact3d/numeric/strategies/limits.hpp"

namespace impact3d::strategies {

template <typename Engine, typename Scalar>
ImpulseSolution<Scalar> brach(const Problem<Scalar>& p, const Brach<Scalar>& spec) {
  ImpulseSolution<Scalar> out;
  out.regime = Regime::as_given;
  out.P_C = Engine::brach_impulse(p, spec.mu_t, spec.mu_z, "brach (eqs 24-27)");
  out.mu_t = out.P_C.y() / out.P_C.x();
  out.mu_z = out.P_C.z() / out.P_C.x();
  const Vec3<Scalar> P_tc = Engine::brach_impulse(p, std::optional<Scalar>(), out.mu_z, "brach critical mu_t (eq 25)");
  const Vec3<Scalar> P_zc = Engine::brach_impulse(p, out.mu_t, std::optional<Scalar>(), "brach critical mu_z (eq 26)");
  out.mu_t_critical = P_tc.y() / P_tc.x();
  out.mu_z_critical = P_zc.z() / P_zc.x();
  flag_if_not_finite(out, *out.mu_t, "mu_t");
  flag_if_not_finite(out, *out.mu_z, "mu_z");
  flag_if_not_finite(out, *out.mu_t_critical, "mu_t critical (eq 25)");
  flag_if_not_finite(out, *out.mu_z_critical, "mu_z critical (eq 26)");
  return out;
}

}  // namespace impact3d::strategies
