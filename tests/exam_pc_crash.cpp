// PC-Crash (eqs 10-20) on a collision whose answer is known by hand: head-on along the line of centres.
#include <catch2/catch.hpp>

#include "support.hpp"

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("head-on along the line of centres: no contact-plane impulse, warned, Full Impact", "[pc-crash]") {
  // Impulse centres on the bodies' x axes, normal along them, collinear approach: K's first row is
  // (1, 0, 0) exactly, so the Full Impact has P_t = P_z = 0 and phi_FI has no direction.
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
  const auto sol = solve_one(s, PcCrash<double>{0.5});
  CHECK(sol.impulse.regime == Regime::full);
  CHECK(sol.impulse.P_C.y() == 0.0);
  CHECK(sol.impulse.P_C.z() == 0.0);
  CHECK(*sol.impulse.gir == 0.0);
  REQUIRE(sol.impulse.warnings.size() == 1);
  CHECK(sol.impulse.warnings[0].code == WarningCode::plane_undefined);
  // m' (1 + e) V_rn, by hand: m' = 720, V_rn = 25.
  CHECK(sol.impulse.P_C.x() == Approx(720 * 1.2 * 25).epsilon(8 * eps));
}
