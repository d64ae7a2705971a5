// Full Impact (eqs 10-12) on seeded random collisions, against its defining properties and against
// Cramer's rule written out here.
#include <catch2/catch.hpp>

#include "support.hpp"

namespace check_full_impact {

using namespace impact3d;
using namespace impact3d::test;

namespace {

Scene<double> with_restitution(Scene<double> s, double e) {
  s.restitution = e;
  return s;
}

double energy_after(const Scene<double>& s, const V3& P_C) {
  const V3 P_W = s.R_WC * P_C;
  return kinetic_energy(apply_impulse(s.body[0], P_W)) + kinetic_energy(apply_impulse(s.body[1], V3(-P_W)));
}

}  // namespace

TEST_CASE("Full Impact at eps = 0 leaves no relative velocity", "[full]") {
  std::mt19937_64 g(51);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = with_restitution(random_scene(g), 0.0);
    const auto sol = solve_one(s, PcCrash<double>{1e6});
    REQUIRE(sol.impulse.regime == Regime::full);
    const double kappa = analyze(s, {PcCrash<double>{0}}).kappa;
    CHECK(sol.V_rf.cwiseAbs().maxCoeff() <= rounding::velocity_roundoff(s, kappa));
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

TEST_CASE("Full Impact at eps > 0 leaves -eps times the whole initial relative velocity", "[full]") {
  std::mt19937_64 g(52);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const auto sol = solve_one(s, PcCrash<double>{1e6});
    const double kappa = analyze(s, {PcCrash<double>{0}}).kappa;
    CHECK((sol.V_rf + s.restitution * sol.V_ri).cwiseAbs().maxCoeff() <= rounding::velocity_roundoff(s, kappa));
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

TEST_CASE("Full Impact at eps = 0 loses more energy than any impulse with the same P_n", "[full]") {
  std::mt19937_64 g(53);
  std::normal_distribution<double> gauss;
  int checked = 0;
  for (int n = 0; n < 100; ++n) {
    const Scene<double> s = with_restitution(random_scene(g), 0.0);
    const V3 P = solve_one(s, PcCrash<double>{1e6}).impulse.P_C;
    const double E = energy_after(s, P);
    for (int k = 0; k < 12; ++k) {
      // Neighbours 1e-3 |P| away in the contact plane: the energy rises by about (1e-3 |P|)^2 / (2 m'),
      // some 1e-7 of the energy, far above its rounding (1e-16 relative).
      const double dz = gauss(g), dt = gauss(g);  // the last first, as draw3 (support.hpp)
      V3 d(0, dt, dz);
      d *= 1e-3 * P.norm() / d.norm();
      CHECK(energy_after(s, P + d) > E);
    }
    ++checked;
  }
  CHECK(checked == 100);  // nothing in the loop skips a case
}

TEST_CASE("Full Impact equals eqs 10-12 (Cramer's rule, written out)", "[full]") {
  std::mt19937_64 g(54);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const auto a = analyze(s, {PcCrash<double>{1e6}});
    const M3& K = a.K;
    const double a1 = K(0, 0), b1 = K(0, 1), c1 = K(0, 2), a2 = K(1, 0), b2 = K(1, 1), c2 = K(1, 2), a3 = K(2, 0),
                 b3 = K(2, 1), c3 = K(2, 2);
    const double Vn = a.V_ri.x(), Vt = a.V_ri.y(), Vz = a.V_ri.z(), f = a.m_prime * (1 + s.restitution);
    const double D = a1 * (b2 * c3 - b3 * c2) + b1 * (a3 * c2 - a2 * c3) + c1 * (a2 * b3 - a3 * b2);
    const V3 ref(f * (Vn * (b2 * c3 - b3 * c2) + Vt * (b3 * c1 - b1 * c3) + Vz * (b1 * c2 - b2 * c1)) / D,
                 f * (Vn * (a3 * c2 - a2 * c3) + Vt * (a1 * c3 - a3 * c1) + Vz * (a2 * c1 - a1 * c2)) / D,
                 f * (Vn * (a2 * b3 - a3 * b2) + Vt * (a3 * b1 - a1 * b3) + Vz * (a1 * b2 - a2 * b1)) / D);
    // Two solutions of one 3x3 system: each within about eps kappa of the exact one.
    CHECK((a.solutions[0].impulse.P_C - ref).norm() <= rounding::solve_roundoff(a.kappa, ref.norm()));
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

}  // namespace check_full_impact
