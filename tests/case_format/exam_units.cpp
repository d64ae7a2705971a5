// US and SI versions of the same case (the bundled examples/us_pickup_into_sedan.json) give the same
// physics. The SI twin is made here with the exact definitions of the case-format contract ("Units"),
// typed in independently of units.hpp: 1 lb = 0.45359237 kg, 1 ft = 0.3048 m, 1 mph = 0.44704 m/s and
// g0 = 9.80665 m/s^2 (the international yard and pound of 1959 and the standard gravity of the 3rd
// CGPM, 1901). Derived here: 1 lbf = lb g0 N; 1 slug ft^2 = 1 lbf s^2 ft = (lbf ft) kg m^2, and
// 1 ft lbf = (lbf ft) J, the same number; 1 deg = pi/180 rad.
// The known answer is the identity of the two solutions, to within the rounding of the conversions.
#include <catch2/catch.hpp>
#include <cmath>

#include <nlohmann/json.hpp>

#include "case_files.hpp"

namespace exam_units {

using namespace impact3d;
using namespace impact3d::test;

namespace {

const double lb = 0.45359237, ft = 0.3048, mph = 0.44704, g0 = 9.80665;  // exact definitions (see above)
const double lbf = lb * g0, slug_ft2 = lbf * ft, deg = M_PI / 180;

void convert(case_format::Number& n, double factor) {
  n.value *= factor;
  n.text = case_format::scalar_to_text(n.value);
}

case_format::CaseSpec si_twin(case_format::CaseSpec c) {
  c.units = Units::SI;
  for (auto& v : c.vehicles) {
    convert(v.mass, lb);
    for (auto& row : v.inertia)
      for (auto& x : row) convert(x, slug_ft2);
    for (auto& x : v.velocity) convert(x, mph);
    for (auto& x : v.angular_velocity) convert(x, deg);
    for (auto& x : v.impulse_center) convert(x, ft);
  }
  return c;
}

}  // namespace

TEST_CASE("the US example and its SI twin give the same physics and consistent output", "[units]") {
  const case_format::CaseSpec us = load_spec(example("us_pickup_into_sedan.json"));
  REQUIRE(us.units == Units::US);
  const case_format::CaseSpec si = si_twin(us);
  const auto a = analyze(case_format::to_scene<double>(us), case_format::to_strategies<double>(us));
  const auto b = analyze(case_format::to_scene<double>(si), case_format::to_strategies<double>(si));
  // Each converted input is rounded once (here and in the library, in different orders), so inputs
  // differ by an eps or two; results move by that times kappa(K) and a few roundings more.
  const double tol = rounding::agreement_bound(a.kappa);
  CHECK((a.K - b.K).norm() <= tol * a.K.norm());
  for (std::size_t k = 0; k < a.solutions.size(); ++k) {
    CHECK((a.solutions[k].impulse.P_C - b.solutions[k].impulse.P_C).norm() <= tol * a.solutions[k].impulse.P_C.norm());
    CHECK(a.solutions[k].energy_loss == Approx(b.solutions[k].energy_loss).epsilon(tol));
  }

  // Output in the case's units: lbf s, mph, deg/s, ft lbf. Velocities are compared against the scale of
  // the collision's point velocities (m/s), angular velocities absolutely (rad/s, below 1 here).
  const double speed = velocity_scale(case_format::to_scene<double>(si));
  const auto ju = nlohmann::json::parse(case_format::result_json(us, a, "double"));
  const auto js = nlohmann::json::parse(case_format::result_json(si, b, "double"));
  CHECK(ju["units"] == "US");
  for (std::size_t k = 0; k < a.solutions.size(); ++k) {
    const auto &ru = ju["results"][k], &rs = js["results"][k];
    for (int c = 0; c < 3; ++c) {
      CHECK(ru["impulse"]["contact"][c].get<double>() * lbf ==
            Approx(rs["impulse"]["contact"][c].get<double>()).epsilon(tol).margin(tol * a.solutions[k].impulse.P_C.norm()));
      CHECK(ru["vehicles"][0]["velocity"][c].get<double>() * mph ==
            Approx(rs["vehicles"][0]["velocity"][c].get<double>()).epsilon(tol).margin(tol * speed));
      CHECK(ru["vehicles"][1]["angular_velocity"][c].get<double>() * deg ==
            Approx(rs["vehicles"][1]["angular_velocity"][c].get<double>()).epsilon(tol).margin(tol));
    }
    CHECK(ru["energy"]["loss"].get<double>() * slug_ft2 == Approx(rs["energy"]["loss"].get<double>()).epsilon(tol));
  }
}

}  // namespace exam_units
