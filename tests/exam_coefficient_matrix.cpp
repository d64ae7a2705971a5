// K (eq 9) of a collision simple enough to derive by hand.
#include <catch2/catch.hpp>

#include "support.hpp"

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("K of two equal spheres struck on their x axes, derived by hand", "[K]") {
  // m = 1000, J = 500 I, r = (1, 0, 0): [r]x^T J^-1 [r]x = diag(0, 1, 1) / 500, m' = 500, so
  // K = I + 500 * 2 * diag(0, 1, 1) / 500 = diag(1, 3, 3).
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
  CHECK((K - ref).cwiseAbs().maxCoeff() <= 4 * eps);  // a handful of exact-ish products and one solve
}
