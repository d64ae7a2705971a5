// Brach's independent impulse ratios (eqs 23-27) on seeded random collisions, against the printed closed
// forms and the Critical Impulse Line.
#include <catch2/catch.hpp>

#include "plane_closed_forms.hpp"

namespace check_brach {

using namespace impact3d;
using namespace impact3d::test;

namespace {

// eqs 25-26 with the coefficients of eq 9.
struct Critical {
  double eta_t, mu_tc0, eta_z, mu_zc0;
  double dt, dz, r, rz;  // the denominators of eqs 25 and 26, and the velocity ratios
};

Critical eqs25_26(const M3& K, const V3& V, double e) {
  const double a1 = K(0, 0), b1 = K(0, 1), c1 = K(0, 2), a2 = K(1, 0), b2 = K(1, 1), c2 = K(1, 2), a3 = K(2, 0),
               b3 = K(2, 1), c3 = K(2, 2);
  const double r = V.y() / V.x(), rz = V.z() / V.x();
  const double dt = (1 + e) * b2 - r * b1, dz = (1 + e) * c3 - rz * c1;
  return {(r * c1 - (1 + e) * c2) / dt, (r * a1 - (1 + e) * a2) / dt, (rz * b1 - (1 + e) * b3) / dz,
          (rz * a1 - (1 + e) * a3) / dz, dt, dz, r, rz};
}

}  // namespace

TEST_CASE("given ratios: P = (1, mu_t, mu_z) P_n with P_n of eq 24", "[brach]") {
  std::mt19937_64 g(81);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const double mu_t = 0.3, mu_z = -0.15;
    const auto a = analyze(s, {Brach<double>{mu_t, mu_z}});
    const V3& P = a.solutions[0].impulse.P_C;
    const double Pn = a.m_prime * (1 + s.restitution) * a.V_ri.x() / (a.K(0, 0) + mu_t * a.K(0, 1) + mu_z * a.K(0, 2));
    CHECK(P.x() == Approx(Pn).epsilon(rounding::relative_bound(a.kappa)));
    CHECK(P.y() == Approx(mu_t * Pn).epsilon(rounding::relative_bound(a.kappa)));
    CHECK(P.z() == Approx(mu_z * Pn).epsilon(rounding::relative_bound(a.kappa)));
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

TEST_CASE("critical ratios equal eqs 25 and 26", "[brach]") {
  std::mt19937_64 g(82);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const double mu_t = 0.25, mu_z = 0.1;
    const auto a = analyze(s, {Brach<double>{mu_t, mu_z}, Brach<double>{std::nullopt, mu_z}, Brach<double>{mu_t, std::nullopt}});
    const Critical c = eqs25_26(a.K, a.V_ri, s.restitution);
    // Each is a quotient whose denominator may cancel; its own conditioning sets the bound (the other
    // ratio enters the numerator with weight |mu| <= 1 here, covered by the (1 + |mu|) factor).
    const double e = s.restitution, mt = c.eta_t * mu_z + c.mu_tc0, mz = c.eta_z * mu_t + c.mu_zc0;
    const double tol_t = 2 * quotient_tolerance(mt, c.dt, a.K, c.r, e), tol_z = 2 * quotient_tolerance(mz, c.dz, a.K, c.rz, e);
    CHECK(std::abs(*a.solutions[0].impulse.mu_t_critical - mt) <= tol_t);
    CHECK(std::abs(*a.solutions[0].impulse.mu_z_critical - mz) <= tol_z);
    CHECK(std::abs(*a.solutions[1].impulse.mu_t - mt) <= tol_t);
    CHECK(std::abs(*a.solutions[2].impulse.mu_z - mz) <= tol_z);
    const double scale = rounding::velocity_roundoff(s, a.kappa);
    CHECK(std::abs(a.solutions[1].V_rf.y()) <= scale);
    CHECK(std::abs(a.solutions[2].V_rf.z()) <= scale);
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

TEST_CASE("both critical: no sliding at all, on the Critical Impulse Line (eq 27)", "[brach]") {
  std::mt19937_64 g(83);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const auto a = analyze(s, {Brach<double>{std::nullopt, std::nullopt}});
    const auto& sol = a.solutions[0];
    const double vtol = rounding::velocity_roundoff(s, a.kappa);
    CHECK(std::abs(sol.V_rf.y()) <= vtol);
    CHECK(std::abs(sol.V_rf.z()) <= vtol);
    // On the line through the maximum-energy-loss impulse along the CIL direction.
    const V3 off = sol.impulse.P_C - a.space.P_max_loss;
    CHECK(off.cross(a.space.cil_direction).norm() <= rounding::agreement_bound(a.kappa) * sol.impulse.P_C.norm());
    const Critical c = eqs25_26(a.K, a.V_ri, s.restitution);
    // eq 27 composes two quotients and divides by 1 - eta_t eta_z: the bound of each quotient, scaled
    // by how much eq 27 amplifies its inputs.
    const double e = s.restitution, den = 1 - c.eta_t * c.eta_z;
    const double mt = (c.eta_t * c.mu_zc0 + c.mu_tc0) / den, mz = (c.eta_z * c.mu_tc0 + c.mu_zc0) / den;
    const double amp = (1 + std::abs(c.eta_t)) * (1 + std::abs(c.eta_z)) * (1 + std::abs(mt) + std::abs(mz)) / std::abs(den);
    const double q = std::max(quotient_tolerance(1.0, c.dt, a.K, c.r, e), quotient_tolerance(1.0, c.dz, a.K, c.rz, e));
    CHECK(std::abs(*sol.impulse.mu_t - mt) <= 4 * amp * q);
    CHECK(std::abs(*sol.impulse.mu_z - mz) <= 4 * amp * q);
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

TEST_CASE("the Critical Impulse Line direction solves K d ~ e_n", "[brach]") {
  // Along the CIL only the normal relative velocity changes: K d has no t or z component.
  std::mt19937_64 g(84);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const auto a = analyze(random_scene(g), {PcCrash<double>{0}});
    const V3 Kd = a.K * a.space.cil_direction;
    CHECK(std::abs(Kd.y()) <= rounding::arithmetic_roundoff(a.K.norm()));
    CHECK(std::abs(Kd.z()) <= rounding::arithmetic_roundoff(a.K.norm()));
    CHECK(Kd.x() > 0);
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

}  // namespace check_brach
