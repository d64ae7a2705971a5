// Never silently wrong, on a named input: the ill-conditioned tensor that motivated the rounding warning.
#include <catch2/catch.hpp>

#include "impact3d/io/read_case.hpp"
#include "impact3d/numeric/multiprecision.hpp"
#include "impact3d/numeric/precision_warnings.hpp"

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
  const io::CaseSpec spec = io::read_case(text);
  for (Engine engine : {Engine::generated, Engine::direct}) {
    try {
      const auto a = analyze(io::to_scene<double>(spec), io::to_strategies<double>(spec), engine);
      CHECK(has(a.solutions[0].warnings, WarningCode::rounding));
    } catch (const SolveError&) {
    }
    const auto ld = analyze(io::to_scene<long double>(spec), io::to_strategies<long double>(spec), engine);
    CHECK(has(ld.solutions[0].warnings, WarningCode::rounding));
    const auto wide = analyze(io::to_scene<mp::float100>(spec), io::to_strategies<mp::float100>(spec), engine);
    CHECK(wide.solutions[0].warnings.empty());
  }
}
