// K (eq 9) on seeded random collisions against values obtained without it: the relative-velocity change
// that unit impulses produce when applied to the bodies by the Newton-Euler impulse equations, its
// symmetry and definiteness, and the paper's Appendix A kernel under its assumptions. The hand-derived
// K is in exam_coefficient_matrix.cpp.
#include <catch2/catch.hpp>

#include "impact3d/generated/coefficient_matrix_appendix_a.hpp"
#include "support.hpp"

namespace check_coefficient_matrix {

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("each column of K is the relative-velocity change of a unit impulse", "[K]") {
  std::mt19937_64 g(21);
  int checked = 0;
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
      const double tol = 16 * eps * velocity_scale(s) * m_prime + rounding::arithmetic_roundoff(K.norm());
      CHECK((-m_prime * dV - K.col(k)).cwiseAbs().maxCoeff() <= tol);
    }
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

TEST_CASE("K is symmetric positive definite", "[K]") {
  std::mt19937_64 g(22);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const M3 K = direct::coefficient_matrix(random_scene(g));
    // Symmetric in exact arithmetic (T S^T J^-1 S T^T is a congruence of the SPD J^-1); the Cholesky
    // solve leaves a few eps of asymmetry relative to |K|.
    CHECK((K - K.transpose()).cwiseAbs().maxCoeff() <= rounding::arithmetic_roundoff(K.norm()));
    Eigen::SelfAdjointEigenSolver<M3> eig(K);
    CHECK(eig.eigenvalues().minCoeff() >= 1.0 - rounding::arithmetic_roundoff(K.norm()));  // K = I + positive semidefinite
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

TEST_CASE("the Appendix A kernel (c3 corrected) equals K under its assumptions", "[K]") {
  // Level vehicles, diagonal tensors, horizontal normal with a rolled tangent: the paper's special case.
  std::mt19937_64 g(23);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    Scene<double> s;
    for (auto& b : s.body) {
      b.mass = 800 + 2500 * u(g);
      b.J_B = draw3(g, {300, 1300}, {1200, 5200}, {1500, 6000}).asDiagonal();
      b.R_WB = rotation_zyx_deg(-180 + 360 * u(g), 0.0, 0.0);
      b.p_CgIc_B = draw3(g, {-2.5, 2.5}, {-1, 1}, {-0.5, 0.5});
    }
    const double nyaw = -180 + 360 * u(g), roll = -40 + 80 * u(g);
    s.R_WC = rotation_zyx_deg(nyaw, 0.0, roll);
    const M3 K = direct::coefficient_matrix(s);
    auto yaw = [&](int i) { return std::atan2(s.body[i].R_WB(1, 0), s.body[i].R_WB(0, 0)); };
    const M3 KA = generated::coefficient_matrix_appendix_a(reduced_mass(s), V3(s.body[0].J_B.diagonal()),
                                                           V3(s.body[1].J_B.diagonal()), s.body[0].p_CgIc_B,
                                                           s.body[1].p_CgIc_B, nyaw * M_PI / 180 - yaw(0),
                                                           nyaw * M_PI / 180 - yaw(1), roll * M_PI / 180);
    // Both sum a few dozen O(|K|) products of sines and cosines accurate to a few eps.
    CHECK((K - KA).cwiseAbs().maxCoeff() <= 4 * rounding::arithmetic_roundoff(K.norm()));
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

}  // namespace check_coefficient_matrix
