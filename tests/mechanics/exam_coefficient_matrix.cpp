// K (eq 9) of a collision simple enough to derive by hand: the derivation is in the comment, the value
// exact.
#include <catch2/catch.hpp>

#include "support.hpp"

namespace exam_coefficient_matrix {

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("K of two equal spheres struck on their x axes, derived by hand", "[K]") {
  // Hand derivation. Eq 8 in the contact frame (here the world and body frames, all identity):
  //   m' (V_rf - V_ri) = -K P,  K = m' [(1/m1 + 1/m2) I + sum_i [r_i]x^T J_i^-1 [r_i]x].
  // m1 = m2 = 1000, so m' = m1 m2 / (m1 + m2) = 500 and m' (1/m1 + 1/m2) = 1. J = 500 I and
  // r = (+-1, 0, 0), so [r]x^T [r]x = |r|^2 I - r r^T = diag(0, 1, 1) and each body adds
  // m' diag(0, 1, 1) / 500 = diag(0, 1, 1). K = I + 2 diag(0, 1, 1) = diag(1, 3, 3), exactly.
  Scene<double> s;
  for (auto& b : s.body) {
    b.mass = 1000;
    b.J_B = 500 * M3::Identity();
    b.R_WB = M3::Identity();
    b.v_W = V3::Zero();
    b.w_B = V3::Zero();
  }
  s.body[0].p_CgIc_B = V3(1, 0, 0);
  s.body[1].p_CgIc_B = V3(-1, 0, 0);
  s.R_WC = M3::Identity();
  const M3 K = direct::coefficient_matrix(s);
  M3 ref = V3(1, 3, 3).asDiagonal();
  // 1/500 and m' 1/500 each round once, and the inverse of J is one solve: a few eps of |K| = O(1).
  CHECK((K - ref).cwiseAbs().maxCoeff() <= 4 * eps);
}

}  // namespace exam_coefficient_matrix
