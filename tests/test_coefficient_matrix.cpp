// K (eq 9) against values obtained without it: a hand derivation, and the relative-velocity change
// that unit impulses produce when applied to the bodies by the Newton-Euler impulse equations.
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

TEST_CASE("each column of K is the relative-velocity change of a unit impulse", "[K]") {
  std::mt19937_64 g(21);
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const M3 K = direct::coefficient_matrix(s);
    const double m_prime = reduced_mass(s);
    for (int k = 0; k < 3; ++k) {
      const V3 P_W = s.R_WC.col(k);  // unit impulse on vehicle 1 along contact axis k
      Scene<double> after = s;
      after.body = {apply_impulse(s.body[0], P_W), apply_impulse(s.body[1], V3(-P_W))};
      const V3 dV = relative_velocity_C(after) - relative_velocity_C(s);
      // dV is a difference of velocities of size velocity_scale, so it carries an absolute error of a
      // few eps of that scale; times m' it must match column k of K.
      const double tol = 16 * eps * velocity_scale(s) * m_prime + 16 * eps * K.norm();
      CHECK((-m_prime * dV - K.col(k)).cwiseAbs().maxCoeff() <= tol);
    }
  }
}

TEST_CASE("K is symmetric positive definite", "[K]") {
  std::mt19937_64 g(22);
  for (int n = 0; n < 300; ++n) {
    const M3 K = direct::coefficient_matrix(random_scene(g));
    // Symmetric in exact arithmetic (T S^T J^-1 S T^T is a congruence of the SPD J^-1); the Cholesky
    // solve leaves a few eps of asymmetry relative to |K|.
    CHECK((K - K.transpose()).cwiseAbs().maxCoeff() <= 16 * eps * K.norm());
    Eigen::SelfAdjointEigenSolver<M3> eig(K);
    CHECK(eig.eigenvalues().minCoeff() >= 1.0 - 16 * eps * K.norm());  // K = I + positive semidefinite
  }
}
