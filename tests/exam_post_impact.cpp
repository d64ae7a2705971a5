// Post-impact reporting: principal direction of force, sliding classification, swerve, and warnings.
#include <catch2/catch.hpp>
#include <cmath>

#include "plane_closed_forms.hpp"

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
    const auto ch = change_for(c.yaw, c.dv);
    REQUIRE(ch.pdof_deg);
    // atan2 and the degree conversion round a few times on values up to 360.
    CHECK(*ch.pdof_deg == Approx(c.pdof).margin(360 * 8 * eps));
    CHECK(*ch.clock == c.clock);
    CHECK(ch.dv == Approx(c.dv.norm()).epsilon(4 * eps));
  }
  CHECK(!change_for(30, V3(0, 0, 1.5)).pdof_deg);  // purely vertical: no direction in the x-y plane
}

TEST_CASE("sliding along an axis: none, started, continued, stopped, reversed", "[classification]") {
  const double tol = 1e-12;
  CHECK(axis_change(5.0, 2.0, tol) == AxisChange::continued);
  CHECK(axis_change(5.0, -1.0, tol) == AxisChange::reversed);
  CHECK(axis_change(-5.0, 1.0, tol) == AxisChange::reversed);
  CHECK(axis_change(5.0, 1e-14, tol) == AxisChange::stopped);
  CHECK(axis_change(0.0, 0.3, tol) == AxisChange::started);
  CHECK(axis_change(0.0, 0.0, tol) == AxisChange::none);
}

TEST_CASE("a pulling contact and an energy gain are computed and flagged", "[warnings]") {
  const io::CaseSpec c = load_spec(example("fig8_side_impact.json"));
  const Scene<double> s = io::to_scene<double>(c);
  // Here b1 < 0, so a1 + mu_t b1 < 0 for mu_t = 10: eq 24 gives P_n < 0.
  const auto pull = solve_one(s, Brach<double>{10.0, 0.0});
  CHECK(pull.impulse.P_C.x() < 0);
  auto has = [](const Solution<double>& sol, WarningCode code) {
    for (const auto& w : sol.warnings)
      if (w.code == code) return true;
    return false;
  };
  CHECK(has(pull, WarningCode::tensile_normal_impulse));
  // A contact-plane impulse pushing along the sliding (mu_t < 0) feeds energy in.
  const auto push = solve_one(s, Brach<double>{-2.0, 0.0});
  CHECK(push.energy_loss < 0);
  CHECK(has(push, WarningCode::energy_gained));
  // And none of the example's own solutions is flagged.
  for (const auto& sol : analyze(s, io::to_strategies<double>(c)).solutions) CHECK(sol.warnings.empty());
}
