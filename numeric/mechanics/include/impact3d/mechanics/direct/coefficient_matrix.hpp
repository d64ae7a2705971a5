// K of eq 9, assembled numerically from the full tensors: m' (V_rf - V_ri) = -K P.
//
// From eq 8, with (J^-1 (r x p)) x r = [r]x^T J^-1 [r]x p:
//   K = I + m' sum_i T_i [r_i]x^T J_i^-1 [r_i]x T_i^T.
// No Appendix A simplification: products of inertia, pitched or rolled vehicles and tilted normals all
// enter through J_i and T_i. J_i^-1 is never formed; each [r_i]x column is solved through Cholesky.
#pragma once

#include <Eigen/Cholesky>

#include "impact3d/mechanics/kinematics.hpp"

namespace impact3d::direct {

template <typename Scalar>
Mat3<Scalar> coefficient_matrix(const Scene<Scalar>& s) {
  const Scalar m_prime = reduced_mass(s);
  Mat3<Scalar> K = Mat3<Scalar>::Identity();
  for (int i = 0; i < 2; ++i) {
    const auto& b = s.body[i];
    const Mat3<Scalar> S = skew(b.p_CgIc_B);
    const Mat3<Scalar> JinvS = spd_solve(b.J_B, S);
    const Mat3<Scalar> T = R_CB(s, i);
    K += m_prime * (T * (S.transpose() * JinvS) * T.transpose());
  }
  return K;
}

}  // namespace impact3d::direct
