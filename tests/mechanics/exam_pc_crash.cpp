// PC-Crash (eqs 10-20) on a collision whose answer is derived by hand below: head-on along the line of
// centres, in both engines (the direct 3x3 solves and the generated closed forms).
#include <catch2/catch.hpp>

#include "support.hpp"

namespace exam_pc_crash {

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("head-on along the line of centres: no contact-plane impulse, warned, Full Impact", "[pc-crash]") {
  // Impulse centres on the bodies' x axes, normal along them, collinear approach: K's first row is
  // (1, 0, 0) exactly, so the Full Impact has P_t = P_z = 0 and phi_FI has no direction.
  // Hand derivation. r_i = (2.2, 0, 0) in body axes and both body x axes lie along n, so
  // [r]x^T J^-1 [r]x has a zero first row and column: a1 = m' (1/m1 + 1/m2) = 1, b1 = c1 = 0. The
  // approach is along n with no rotation, so V_ri = (25, 0, 0): vehicle 1 at +15 m/s along x, vehicle 2
  // at -10 m/s, and n = -x, so V_rn = -(-10 - 15) = 25. Eqs 10-12 then give P_t = P_z = 0 and
  // P_n = m' (1 + e) V_rn with m' = 1200 * 1800 / 3000 = 720, e = 0.2: P_n = 720 * 1.2 * 25 = 21600.
  // The GIR (eq 14) is |P_cp| / P_n = 0, exactly, since the zeros are exact.
  Scene<double> s;
  for (int i = 0; i < 2; ++i) {
    auto& b = s.body[i];
    b.mass = i ? 1800 : 1200;
    b.J_B = V3(500, 2000, 2200).asDiagonal();
    b.R_WB = rotation_zyx_deg(i ? 180.0 : 0.0, 0.0, 0.0);
    b.v_W = V3(i ? -10 : 15, 0, 0);
    b.w_B = V3::Zero();
    b.p_CgIc_B = V3(2.2, 0, 0);
  }
  s.R_WC = rotation_zyx_deg(180.0, 0.0, 0.0);  // n = -x: into vehicle 1, which is pushed back
  s.restitution = 0.2;
  for (Engine engine : kEngines) {
    INFO(engine_name(engine) << " engine");
    const auto sol = solve_one(s, PcCrash<double>{0.5}, engine);
    CHECK(sol.impulse.regime == Regime::full);
    CHECK(sol.impulse.P_C.y() == 0.0);
    CHECK(sol.impulse.P_C.z() == 0.0);
    CHECK(*sol.impulse.gir == 0.0);
    REQUIRE(sol.impulse.warnings.size() == 1);
    CHECK(sol.impulse.warnings[0].code == WarningCode::plane_undefined);
    // 21600 from m' (1 + e) V_rn: m' = 720 and 1 + e = 1.2 each round once, the product twice more.
    CHECK(sol.impulse.P_C.x() == Approx(720 * 1.2 * 25).epsilon(8 * eps));
  }
}

}  // namespace exam_pc_crash
