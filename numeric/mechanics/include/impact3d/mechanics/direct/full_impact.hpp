// Full Impact (eqs 10-12): all three post-impact relative velocity components are -eps times the
// initial ones, i.e. K P = m' (1 + eps) V_ri. At eps = 0 this is the maximum-energy-loss impulse.
#pragma once

#include "impact3d/mechanics/direct/constraints.hpp"

namespace impact3d::direct {

template <typename Scalar>
std::optional<Vec3<Scalar>> full_impact_impulse(const Problem<Scalar>& p, const Scalar& eps) {
  const Vec3<Scalar> e[3] = {Vec3<Scalar>::UnitX(), Vec3<Scalar>::UnitY(), Vec3<Scalar>::UnitZ()};
  return solve_rows<Scalar>({velocity_row(p, e[0], Scalar(-eps * p.V_ri.x())),
                             velocity_row(p, e[1], Scalar(-eps * p.V_ri.y())),
                             velocity_row(p, e[2], Scalar(-eps * p.V_ri.z()))});
}

}  // namespace impact3d::direct
