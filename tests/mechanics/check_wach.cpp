// Wach's strategy (eqs 21-22) on seeded random collisions: plane along the initial sliding, P_z' = 0,
// ratio capped at CIR or GIR.
#include <catch2/catch.hpp>
#include <cmath>

#include "plane_closed_forms.hpp"

namespace check_wach {

using namespace impact3d;
using namespace impact3d::test;

namespace {

// Wach with mu above the plane's limit, so that the cap applies.
Analysis<double> capped_wach(const Scene<double>& s, WachLimit limit) {
  const auto& imp = solve_one(s, Wach<double>{0.0, limit}).impulse;
  const double value = limit == WachLimit::cir ? *imp.cir : *imp.gir;
  return analyze(s, {Wach<double>{std::max(value, 0.0) + 1.0, limit}});
}

}  // namespace

TEST_CASE("Wach's plane is at phi = atan2(V_rzi, V_rti) with P_t' = mu P_n and P_z' = 0", "[wach]") {
  std::mt19937_64 g(71);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const auto a = analyze(s, {Wach<double>{0.05, WachLimit::cir}});
    const auto& sol = a.solutions[0];
    const double phi = std::atan2(a.V_ri.z(), a.V_ri.y());
    CHECK(std::abs(*sol.impulse.plane_angle_deg * M_PI / 180 - phi) <= 8 * eps);
    const double c = std::cos(phi), sn = std::sin(phi);
    const V3& P = sol.impulse.P_C;
    const double mu = *sol.impulse.mu;
    CHECK(std::abs(-sn * P.y() + c * P.z()) <= rounding::relative_bound(a.kappa) * P.norm());
    CHECK(c * P.y() + sn * P.z() == Approx(mu * P.x()).epsilon(rounding::relative_bound(a.kappa)).margin(rounding::relative_bound(a.kappa) * P.norm()));
    const PlaneCoefficients k = plane_coefficients(a.K, a.V_ri, c, sn);
    CHECK(std::abs(*sol.impulse.cir - eq19_cir(k, s.restitution)) <= ratio_tolerance(k, a.K, s.restitution, *sol.impulse.cir));
    CHECK(std::abs(*sol.impulse.gir - eq20_gir(k)) <= ratio_tolerance(k, a.K, 0.0, *sol.impulse.gir));
    CHECK(P.x() == Approx(eq18_Pn(k, a.m_prime, s.restitution, a.V_ri.x(), mu)).epsilon(rounding::relative_bound(a.kappa)));
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

TEST_CASE("Wach capped at its CIR leaves only out-of-plane sliding (swerve)", "[wach]") {
  std::mt19937_64 g(72);
  int swerving = 0;
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const auto a = capped_wach(s, WachLimit::cir);
    const auto& sol = a.solutions[0];
    REQUIRE(sol.impulse.regime == Regime::capped);
    const auto [along, across] = plane_components(*sol.impulse.plane_angle_deg * M_PI / 180, sol.V_rf);
    const double tol = rounding::velocity_roundoff(s, a.kappa);
    CHECK(std::abs(along) <= tol);
    // What is left is the swerve: sliding across the initial direction, as the report computes it.
    CHECK(std::abs(sol.sliding_after - std::abs(across)) <= tol);
    CHECK(std::abs(*sol.swerve_speed - across) <= tol);
    if (std::abs(across) > 1e-3) ++swerving;  // 1 mm/s: a swerve, not rounding
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
  CHECK(swerving > 250);  // off the Critical Impulse Line the swerve is generic, not an exception
}

TEST_CASE("Wach capped at its GIR reverses in-plane sliding by eps, like Full Impact", "[wach]") {
  std::mt19937_64 g(73);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const auto a = capped_wach(s, WachLimit::gir);
    const auto& sol = a.solutions[0];
    REQUIRE(sol.impulse.regime == Regime::capped);
    const double phi = *sol.impulse.plane_angle_deg * M_PI / 180;
    const double along_i = plane_components(phi, sol.V_ri).along, along_f = plane_components(phi, sol.V_rf).along;
    CHECK(std::abs(along_f + s.restitution * along_i) <= rounding::velocity_roundoff(s, a.kappa));
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

}  // namespace check_wach
