// Brach: independent impulse ratios P_t = mu_t P_n, P_z = mu_z P_n (eqs 23-24); a ratio given as
// "critical" is replaced by the condition that sliding along its axis stops (eqs 25-26, both: eq 27).
// The critical ratio of each axis, given the other ratio as used, is reported as a limit.
#pragma once

#include "impact3d/numeric/direct/constraints.hpp"
#include "impact3d/numeric/direct/limits.hpp"

namespace impact3d::direct {

template <typename Scalar>
ImpulseSolution<Scalar> solve_brach(const Problem<Scalar>& p, const Brach<Scalar>& spec) {
  const Vec3<Scalar> e_t = Vec3<Scalar>::UnitY(), e_z = Vec3<Scalar>::UnitZ();
  auto axis_row = [&](const Vec3<Scalar>& e, const std::optional<Scalar>& mu) {
    return mu ? ratio_row(e, *mu) : no_sliding_row(p, e);
  };
  ImpulseSolution<Scalar> out;
  out.regime = Regime::as_given;
  out.P_C = solve_rows<Scalar>({restitution_row(p, p.restitution), axis_row(e_t, spec.mu_t), axis_row(e_z, spec.mu_z)},
                               "brach (eqs 24-27)");
  out.mu_t = out.P_C.y() / out.P_C.x();
  out.mu_z = out.P_C.z() / out.P_C.x();
  const Vec3<Scalar> P_tc =
      solve_rows<Scalar>({restitution_row(p, p.restitution), no_sliding_row(p, e_t), ratio_row(e_z, *out.mu_z)},
                         "brach critical mu_t (eq 25)");
  const Vec3<Scalar> P_zc =
      solve_rows<Scalar>({restitution_row(p, p.restitution), ratio_row(e_t, *out.mu_t), no_sliding_row(p, e_z)},
                         "brach critical mu_z (eq 26)");
  out.mu_t_critical = P_tc.y() / P_tc.x();
  out.mu_z_critical = P_zc.z() / P_zc.x();
  flag_if_not_finite(out, *out.mu_t, "mu_t");
  flag_if_not_finite(out, *out.mu_z, "mu_z");
  flag_if_not_finite(out, *out.mu_t_critical, "mu_t critical (eq 25)");
  flag_if_not_finite(out, *out.mu_z_critical, "mu_z critical (eq 26)");
  return out;
}

}  // namespace impact3d::direct
