// Post-impact reporting on named inputs: the principal direction of force of hand-chosen velocity
// changes (the convention of post_impact.hpp and docs/case-format.md's result keys: degrees clockwise from
// straight ahead seen from above, 0 = frontal, 90 = right side, and the nearest clock hour), the sliding
// classification of hand-picked before/after pairs, and the warnings of the Figure 8 example under
// strategies chosen by hand to pull and to feed energy in.
#include <catch2/catch.hpp>
#include <cmath>

#include "case_files.hpp"

namespace exam_post_impact {

using namespace impact3d;
using namespace impact3d::test;

namespace {

BodyChange<double> change_for(double yaw_deg, const V3& dv_W) {
  RigidBody<double> before;
  before.R_WB = rotation_zyx_deg(yaw_deg, 0.0, 0.0);
  before.v_W = V3(3, -2, 0);
  RigidBody<double> after = before;
  after.v_W += dv_W;
  return body_change(before, after);
}

}  // namespace

TEST_CASE("PDOF: clockwise from straight ahead, the side the force comes from", "[pdof]") {
  // Each row by hand: the force on the vehicle is along its Delta-V, so it comes from the side opposite
  // Delta-V; PDOF = atan2(dv_y, -dv_x) in body axes (y left), in [0, 360); clock = round(PDOF / 30),
  // with 0 read as 12.
  struct Case {
    double yaw;
    V3 dv;
    double pdof;
    int clock;
  };
  const double c40 = std::cos(40 * M_PI / 180), s40 = std::sin(40 * M_PI / 180);
  const Case cases[] = {
      {0, V3(-2, 0, 0), 0, 12},      // frontal: pushed rearward
      {0, V3(0, 2, 0), 90, 3},       // struck on the right: pushed to the left (+y)
      {0, V3(2, 0, 0), 180, 6},      // rear
      {0, V3(0, -2, 0), 270, 9},     // left side
      {0, V3(-c40, s40, 0), 40, 1},  // right front
      {90, V3(2, 0, 0), 270, 9},     // heading +y, pushed along +x world = to its right: struck on the left
      {90, V3(0, -2, 0), 0, 12},     // heading +y, pushed back
  };
  for (const auto& c : cases) {
    INFO("yaw " << c.yaw << ", PDOF " << c.pdof);
    const auto ch = change_for(c.yaw, c.dv);
    REQUIRE(ch.pdof_deg);
    // atan2 and the degree conversion round a few times on values up to 360.
    CHECK(std::abs(*ch.pdof_deg - c.pdof) <= 360 * 8 * eps);
    CHECK(*ch.clock == c.clock);
    CHECK(ch.dv == Approx(c.dv.norm()).epsilon(4 * eps));
  }
  CHECK(!change_for(30, V3(0, 0, 1.5)).pdof_deg);  // purely vertical: no direction in the x-y plane
}

TEST_CASE("sliding along an axis: none, started, continued, stopped, reversed", "[classification]") {
  // The classification's definition: sliding is a speed above tol; its sign before and after decides.
  // tol is the function's threshold argument, not a test tolerance: 1e-14 lies below it, 0.3 above.
  const double tol = 1e-12;
  CHECK(axis_change(5.0, 2.0, tol) == AxisChange::continued);
  CHECK(axis_change(5.0, -1.0, tol) == AxisChange::reversed);
  CHECK(axis_change(-5.0, 1.0, tol) == AxisChange::reversed);
  CHECK(axis_change(5.0, 1e-14, tol) == AxisChange::stopped);
  CHECK(axis_change(0.0, 0.3, tol) == AxisChange::started);
  CHECK(axis_change(0.0, 0.0, tol) == AxisChange::none);
}

TEST_CASE("a pulling contact and an energy gain are computed and flagged", "[warnings]") {
  const case_format::CaseSpec c = load_spec(example("fig8_side_impact.json"));
  const Scene<double> s = case_format::to_scene<double>(c);
  // By hand from the example's K (verification/reference/fig8_side_impact.json): a1 = 1.0583 and
  // b1 = -0.1986, so a1 + mu_t b1 = -0.928 < 0 for mu_t = 10, and eq 24 gives P_n < 0.
  const auto pull = solve_one(s, Brach<double>{10.0, 0.0});
  CHECK(pull.impulse.P_C.x() < 0);
  auto has = [](const Solution<double>& sol, WarningCode code) {
    for (const auto& w : sol.warnings)
      if (w.code == code) return true;
    return false;
  };
  CHECK(has(pull, WarningCode::tensile_normal_impulse));
  // A contact-plane impulse pushing along the sliding (mu_t < 0) feeds energy in. By hand with the same
  // K, m' = 975, V_ri = (11.176, 11.176, 0) and e = 0.1: P_n = 8235 N s, V_rtf = 53.9 m/s (the sliding
  // sped up from 11.2), and the loss P . (V_ri + V_rf) / 2 = -4.9e5 J.
  const auto push = solve_one(s, Brach<double>{-2.0, 0.0});
  CHECK(push.energy_loss < 0);
  CHECK(has(push, WarningCode::energy_gained));
  // And none of the example's own solutions is flagged.
  for (const auto& sol : analyze(s, case_format::to_strategies<double>(c)).solutions) CHECK(sol.warnings.empty());
}

}  // namespace exam_post_impact
