// The fundamental planes of impulse space (paper Figure 2) and the Critical Impulse Line.
//
// With V_rf = V_ri - K P / m', the plane on which the post-impact relative velocity along axis k is zero
// is K_k . P = m' V_rk (K_k the k-th row): k = n is the maximum-compression plane, k = t and k = z the
// no-sliding planes. Their common point is the maximum-energy-loss impulse (Full Impact at eps = 0);
// the t and z planes meet in the Critical Impulse Line, whose direction is K_t x K_z.
#pragma once

#include "impact3d/numeric/problem.hpp"

namespace impact3d {

template <typename Scalar>
struct ImpulseSpace {
  Vec3<Scalar> P_max_loss;         // contact axes
  Vec3<Scalar> cil_direction;      // unit; its P_n component is >= 0
  Mat3<Scalar> plane_normal;       // row k: unit normal of the plane of zero post-impact V_r along axis k
  Vec3<Scalar> plane_offset;       // row k: plane_normal.row(k) . P = plane_offset(k)
  Scalar restitution_offset;       // the case's restitution plane: plane_normal.row(0) . P = this
};

template <typename Engine, typename Scalar>
ImpulseSpace<Scalar> impulse_space(const Problem<Scalar>& p) {
  ImpulseSpace<Scalar> s;
  s.P_max_loss = Engine::full_impact(p, Scalar(0));
  for (int k = 0; k < 3; ++k) {
    const Scalar len = p.K.row(k).norm();
    s.plane_normal.row(k) = p.K.row(k) / len;
    s.plane_offset(k) = p.m_prime * p.V_ri(k) / len;
  }
  s.restitution_offset = p.m_prime * (Scalar(1) + p.restitution) * p.V_ri.x() / p.K.row(0).norm();
  Vec3<Scalar> d = p.K.row(1).transpose().cross(p.K.row(2).transpose());
  if (d.x() < Scalar(0)) d = -d;
  s.cil_direction = d.normalized();
  return s;
}

}  // namespace impact3d
