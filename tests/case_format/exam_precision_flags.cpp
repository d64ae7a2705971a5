// Never silently wrong, on a named input: the ill-conditioned tensor that motivated the rounding warning
// (the Figure 8 vehicles, crossing the other way, with the Malibu's inertia replaced by
// [[1, 0, 0.9999999999], [0, 2500, 0], [0.9999999999, 0, 1]]).
//
// The known answer, by hand from rounding.hpp: a result is flagged when 32 eps A (1 + |V_cp / V_n|)
// exceeds 1e-6, with A = kappa(K) cond(J) max(1, (|v_IC1| + |v_IC2|) / V_rn). The tensor's x-z block
// has eigenvalues 2 - 1e-10 and 1e-10 beside Iyy = 2500, so cond(J) = 2500 / 1e-10 = 2.5e13; kappa(K)
// is then 7.9e12 and A = 4.0e26 (these two as computed by the library). So 32 eps A is 2.8e12 at double (eps 2.2e-16), 1.4e9 at long double
// (1.1e-19) and 2.4e-6 at float128 (1.9e-34): every one above 1e-6, flagged (or, at double, refused as
// singular); at 50 digits (eps 5e-51) it is 7e-23 and at 100 digits smaller still: no warning.
#include <catch2/catch.hpp>

#include "impact3d/case_format/read_case.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "impact3d/mechanics/precision_warnings.hpp"

namespace exam_precision_flags {

using namespace impact3d;

namespace {

bool has(const std::vector<Warning>& ws, WarningCode c) {
  for (const auto& w : ws)
    if (w.code == c) return true;
  return false;
}

}  // namespace

TEST_CASE("the issue's tensor: every precision short of 50 digits flags it or refuses it", "[precision]") {
  const std::string text = R"({"vehicles": [
      {"mass": 1560, "inertia": [[1, 0, 0.9999999999], [0, 2500, 0], [0.9999999999, 0, 1]], "velocity": [0, 11.176, 0],
       "impulse_center": [0.35, -0.90, 0.05]},
      {"mass": 2600, "inertia": {"Ixx": 1100, "Iyy": 5600, "Izz": 5900}, "orientation_deg": {"yaw": 90},
       "velocity": [11.176, 0, 0], "impulse_center": [2.60, 0.20, -0.15]}],
    "contact": {"normal_yaw_deg": 0}, "restitution": 0.1, "strategy": {"name": "pc-crash", "mu": 0.4}})";
  const case_format::CaseSpec spec = case_format::read_case(text);
  for (Engine engine : {Engine::generated, Engine::direct}) {
    INFO(engine_name(engine) << " engine");
    try {
      const auto a = analyze(case_format::to_scene<double>(spec), case_format::to_strategies<double>(spec), engine);
      CHECK(has(a.solutions[0].warnings, WarningCode::rounding));
    } catch (const SolveError&) {
    }
    const auto ld = analyze(case_format::to_scene<long double>(spec), case_format::to_strategies<long double>(spec), engine);
    CHECK(has(ld.solutions[0].warnings, WarningCode::rounding));
    const auto quad = analyze(case_format::to_scene<mp::float128>(spec), case_format::to_strategies<mp::float128>(spec), engine);
    CHECK(has(quad.solutions[0].warnings, WarningCode::rounding));
    const auto f50 = analyze(case_format::to_scene<mp::float50>(spec), case_format::to_strategies<mp::float50>(spec), engine);
    CHECK(f50.solutions[0].warnings.empty());
    const auto wide = analyze(case_format::to_scene<mp::float100>(spec), case_format::to_strategies<mp::float100>(spec), engine);
    CHECK(wide.solutions[0].warnings.empty());
  }
}

}  // namespace exam_precision_flags
