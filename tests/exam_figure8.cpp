// The paper's Figure 8 situation (bundled example): what the paper reports, and its eq 29 argument.
// The example uses stand-in vehicle data, so published magnitudes are compared within 1 mph only.
#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

using namespace impact3d;
using namespace impact3d::test;

namespace {
const double mph = 0.44704;
}

TEST_CASE("Figure 8: mu = 1.0 is a Full Impact that reverses the t sliding", "[figure8]") {
  const io::CaseSpec c = load_spec(example("fig8_side_impact.json"));
  const auto a = analyze(io::to_scene<double>(c), {PcCrash<double>{1.0}, PcCrash<double>{0.4}});
  // The initial sliding is 25 mph along +t (rearward on the Malibu), with no vertical component.
  CHECK(a.V_ri.y() == Approx(25 * mph).epsilon(4 * eps));
  CHECK(a.V_ri.z() == 0.0);
  const auto& full = a.solutions[0];
  CHECK(full.impulse.regime == Regime::full);
  CHECK(full.t_change == AxisChange::reversed);
  CHECK(full.volume == "B");
  // Paper: -2.2 mph after (Virtual CRASH's own vehicle data).
  CHECK(std::abs(full.V_rf.y() / mph - (-2.2)) < 1.0);
}

TEST_CASE("Figure 8: mu = 0.4 is a Sliding Impact with continued t sliding and swerve", "[figure8]") {
  const io::CaseSpec c = load_spec(example("fig8_side_impact.json"));
  const auto a = analyze(io::to_scene<double>(c), {PcCrash<double>{1.0}, PcCrash<double>{0.4}});
  const auto& slide = a.solutions[1];
  CHECK(slide.impulse.regime == Regime::sliding);
  CHECK(slide.t_change == AxisChange::continued);
  CHECK(slide.z_change == AxisChange::started);
  CHECK(std::abs(*slide.swerve_speed) > 0.1 * mph);
  CHECK(std::abs(slide.V_rf.y() / mph - 3.5) < 1.0);  // paper: +3.5 mph
  // Both impulses have a vertical component although the approach is horizontal...
  CHECK(std::abs(a.solutions[0].impulse.P_C.z()) > 1e-3 * a.solutions[0].impulse.P_C.norm());
  CHECK(std::abs(slide.impulse.P_C.z()) > 1e-3 * slide.impulse.P_C.norm());
  // ...and the same P_z / P_t (the paper's eq 29 argument: both lie on the Full Impact plane).
  const double r_full = a.solutions[0].impulse.P_C.z() / a.solutions[0].impulse.P_C.y();
  const double r_slide = slide.impulse.P_C.z() / slide.impulse.P_C.y();
  CHECK(r_slide == Approx(r_full).epsilon(64 * eps * a.kappa));
}

TEST_CASE("Figure 8: Wach's plane is horizontal here and cannot reach the Full Impact", "[figure8]") {
  const io::CaseSpec c = load_spec(example("fig8_side_impact.json"));
  const auto a = analyze(io::to_scene<double>(c), {Wach<double>{100.0, WachLimit::cir}, PcCrash<double>{100.0}});
  const auto& wach = a.solutions[0];
  CHECK(*wach.impulse.plane_angle_deg == 0.0);
  CHECK(wach.impulse.P_C.z() == 0.0);
  CHECK(*a.solutions[1].impulse.plane_angle_deg != 0.0);  // phi_FI differs from phi
  CHECK(std::abs(wach.V_rf.z()) > 0.1 * mph);               // swerve even at Wach's CIR
}
