// The reconstruction summary's quantities on collisions worked by hand: Delta-V in the vehicle's axes,
// speed, heading and yaw rate after, the deformation energy and EES under each split rule, the momentum
// balance, the output units, and the swerve told apart from a reversal.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "case_files.hpp"

namespace exam_reconstruction {

using namespace impact3d;
using namespace impact3d::test;

namespace {

// Vehicle 1 (1000 kg, yawed 30 degrees) moves at 10 m/s along world x into vehicle 2 (1000 kg, at rest),
// both impulse centres at the CGs, the normal along -x (into vehicle 1), restitution 0: a central,
// plastic impact. By momentum both leave at 5 m/s along x: Delta-V_1 = (-5, 0, 0) in the world,
// Delta-V_2 = (5, 0, 0); energy 50 000 J before, 25 000 J after, 25 000 J lost.
std::string central_case(const std::string& split = "") {
  return R"({"name": "central", "vehicles": [
    {"name": "a", "mass": 1000, "inertia": {"Ixx": 400, "Iyy": 1500, "Izz": 1600},
     "orientation_deg": {"yaw": 30}, "velocity": [10, 0, 0], "impulse_center": [0, 0, 0]},
    {"name": "b", "mass": 1000, "inertia": {"Ixx": 400, "Iyy": 1500, "Izz": 1600},
     "velocity": [0, 0, 0], "impulse_center": [0, 0, 0]}],
    "contact": {"normal_yaw_deg": 180}, "restitution": 0,)" +
         split + R"( "strategy": {"name": "pc-crash", "mu": 0.4}})";
}

Solution<double> central_solution(const std::string& split = "") {
  const case_format::CaseSpec spec = case_format::read_case(central_case(split));
  return analyze(case_format::to_scene<double>(spec), case_format::to_strategies<double>(spec)).solutions.at(0);
}

// The rounding of a few operations on numbers of size 10: eps-level, 8 eps relative (rounding.hpp's
// short sums count 16 for longer chains).
constexpr double tol = 8 * eps * 10;

}  // namespace

TEST_CASE("Delta-V in the vehicle's axes: a vehicle yawed 30 degrees, by hand", "[reconstruction]") {
  const auto s = central_solution();
  // R_WB^T (-5, 0, 0) for yaw 30: longitudinal -5 cos 30, lateral +5 sin 30 (pushed back and to its
  // left, since it meets the obstacle with its nose turned 30 degrees to the left of its path).
  CHECK(std::abs(s.motion[0].dv_B.x() - -5 * std::cos(M_PI / 6)) <= tol);
  CHECK(std::abs(s.motion[0].dv_B.y() - 2.5) <= tol);
  CHECK(std::abs(s.motion[0].dv_B.z()) <= tol);
  // Vehicle 2 is not yawed: its axes are the world's.
  CHECK(std::abs(s.motion[1].dv_B.x() - 5) <= tol);
  CHECK(std::abs(s.motion[1].dv_B.y()) <= tol);
  for (int i = 0; i < 2; ++i) {
    CHECK(std::abs(s.motion[i].speed_after - 5) <= tol);
    REQUIRE(s.motion[i].heading_after_deg);
    CHECK(std::abs(*s.motion[i].heading_after_deg) <= tol);
    CHECK(s.motion[i].yaw_rate_after == 0);  // no lever arm, no angular impulse
  }
}

TEST_CASE("EES under each split rule, by hand", "[reconstruction][ees]") {
  // 25 000 J lost. Equal masses: the default split is half each, EES = sqrt(2 * 12 500 / 1000) = 5 m/s.
  const auto mass = central_solution();
  CHECK(std::abs(mass.energy_loss - 25000) <= 8 * eps * 50000);
  for (int i = 0; i < 2; ++i) {
    CHECK(std::abs(mass.deformation.share[i] - 0.5) <= eps);
    CHECK(std::abs(mass.deformation.energy[i] - 12500) <= 8 * eps * 50000);
    REQUIRE(mass.deformation.ees[i]);
    CHECK(std::abs(*mass.deformation.ees[i] - 5) <= 16 * eps * 5);
  }
  // Shares 3 : 1: 18 750 J and 6 250 J, EES sqrt(37.5) and sqrt(12.5). Stiffnesses 1 : 3 give the same
  // (the energy of one force on a spring of stiffness k is F^2 / 2k).
  for (const char* split : {R"("energy_split": {"share": [3, 1]},)", R"("energy_split": {"stiffness": [1e5, 3e5]},)"}) {
    INFO(split);
    const auto s = central_solution(split);
    CHECK(std::abs(s.deformation.share[0] - 0.75) <= eps);
    CHECK(std::abs(s.deformation.energy[0] - 18750) <= 8 * eps * 50000);
    CHECK(std::abs(*s.deformation.ees[0] - std::sqrt(37.5)) <= 16 * eps * 7);
    CHECK(std::abs(*s.deformation.ees[1] - std::sqrt(12.5)) <= 16 * eps * 7);
  }
  // Unequal masses by default: E_1 : E_2 = m_2 : m_1, so m_1 EES_1 = m_2 EES_2 (each sqrt(2 m' loss)).
  const Scene<double> fig8 = case_format::to_scene<double>(load_spec(example("fig8_side_impact.json")));
  const Analysis<double> a = analyze(fig8, every_strategy(0.4));
  const auto& b = fig8.body;
  for (const auto& s : a.solutions) {
    CHECK(std::abs(b[0].mass * *s.deformation.ees[0] - b[1].mass * *s.deformation.ees[1]) <=
          64 * eps * b[0].mass * *s.deformation.ees[0]);
    CHECK(std::abs(b[0].mass * *s.deformation.ees[0] - std::sqrt(2 * a.m_prime * s.energy_loss)) <=
          64 * eps * b[0].mass * *s.deformation.ees[0]);
  }
}

TEST_CASE("energy_split is read strictly", "[reconstruction][ees]") {
  const auto refused = [](const std::string& split) {
    try {
      (void)case_format::read_case(central_case(split));
    } catch (const case_format::CaseError& e) {
      return e.line();
    }
    return std::string("accepted");
  };
  CHECK(refused(R"("energy_split": {"share": [1, -1]},)") == "$.energy_split.share[1]: must be >= 0 (got -1)");
  CHECK(refused(R"("energy_split": {"share": [0, 0]},)") == "$.energy_split.share: both shares are 0");
  CHECK(refused(R"("energy_split": {"stiffness": [0, 1]},)") == "$.energy_split.stiffness[0]: must be > 0 (got 0)");
  CHECK(refused(R"("energy_split": {"share": [1, 1], "stiffness": [1, 1]},)") ==
        "$.energy_split: give one of \"share\" and \"stiffness\"");
  CHECK(refused(R"("energy_split": {"share": [1]},)") == "$.energy_split.share: expected 2 numbers, one per vehicle, got 1");
  CHECK(refused(R"("energy_split": {"ratio": 1},)") == "$.energy_split.ratio: unknown key (keys starting with '_' are ignored)");
  CHECK(refused(R"("energy_split": {"share": [0, 1]},)") == "accepted");
}

TEST_CASE("a Full Impact that reverses the sliding is a reversal, not a 180-degree swerve", "[reconstruction][swerve]") {
  // Figure 8 at mu = 1.0 (above the GIR): the Full Impact ends the sliding at eps = 0 and, with
  // restitution, turns it back along the line it came (the paper's eqs 10-12 scale the tangential
  // relative velocity by -eps).
  const case_format::CaseSpec spec = load_spec(example("fig8_side_impact.json"));
  const Analysis<double> a = analyze(case_format::to_scene<double>(spec), case_format::to_strategies<double>(spec));
  const auto& full = a.solutions.at(0);
  REQUIRE(full.impulse.regime == Regime::full);
  REQUIRE(full.reversed);
  CHECK(*full.reversed);
  REQUIRE(full.swerve_deg);
  CHECK(*full.swerve_deg == 0);  // back along the line (across within rounding of 0): no swerve off it
  CHECK(*full.sliding_along < 0);
  // Sliding Impact at 0.4: continues, and swerves off the line by the angle of its components.
  const auto& slide = a.solutions.at(1);
  REQUIRE(slide.reversed);
  CHECK_FALSE(*slide.reversed);
  CHECK(std::abs(*slide.swerve_deg - std::atan2(*slide.swerve_speed, *slide.sliding_along) * 180 / M_PI) <= 1e-12);
}

TEST_CASE("momentum: the balance holds within its bound, and a disturbed state is caught", "[reconstruction][momentum]") {
  std::mt19937_64 g(41);
  int checked = 0;
  double worst = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    for (const auto& sol : analyze(s, every_strategy(0.4)).solutions) {
      const auto& m = sol.momentum;
      worst = std::max({worst, m.linear_residual, m.angular_residual[0], m.angular_residual[1]});
      ++checked;
    }
  }
  CHECK(checked == 300 * static_cast<int>(every_strategy(0.4).size()));
  INFO("worst residual over its bound " << worst);
  CHECK(worst <= 1);
  // One vehicle's yaw rate after off by a millionth: the angular balance about its impulse centre fails.
  const Scene<double> s = random_scene(g);
  const auto sol = analyze(s, every_strategy(0.4)).solutions.at(0);
  auto after = sol.after;
  after[1].w_B.z() += 1e-6 * (1 + std::abs(after[1].w_B.z()));
  const auto bad = momentum_check(s.body, after);
  CHECK(bad.angular_residual[1] > 1);
  CHECK(bad.linear_residual <= 1);
}

TEST_CASE("output units: km/h and mph from an SI case, SI from a US case", "[reconstruction][units]") {
  const case_format::CaseSpec si = case_format::read_case(central_case());
  const auto json_in = [&](const case_format::CaseSpec& spec, std::optional<Units> u) {
    case_format::RenderOptions o;
    o.format = case_format::Format::json;
    o.units = u;
    return nlohmann::json::parse(studies::render(spec, "double", o));
  };
  const auto kmh = json_in(si, Units::metric_kmh);
  CHECK(kmh["units"] == "metric-kmh");
  // 5 m/s = 18 km/h exactly in decimal; the double is within a rounding or two of it.
  const double dv = kmh["results"][0]["vehicles"][0]["delta_v_magnitude"];
  CHECK(std::abs(dv - 18) <= 4 * eps * 18);
  const auto us = json_in(si, Units::US);
  const double dv_mph = us["results"][0]["vehicles"][0]["delta_v_magnitude"];
  CHECK(std::abs(dv_mph - 5 / 0.44704) <= 4 * eps * 12);
  const double loss_ftlbf = us["results"][0]["energy"]["loss"];
  CHECK(std::abs(loss_ftlbf - 25000 / (0.3048 * 0.45359237 * 9.80665)) <= 16 * eps * 2e4);
  // The other way: the US example written in SI equals its US numbers times the exact factors.
  const case_format::CaseSpec usc = load_spec(example("us_pickup_into_sedan.json"));
  const auto in_us = json_in(usc, std::nullopt), in_si = json_in(usc, Units::SI);
  CHECK(in_si["units"] == "SI");
  int compared = 0;
  for (std::size_t k = 0; k < in_us["results"].size(); ++k)
    for (int i = 0; i < 2; ++i)
      for (int c = 0; c < 3; ++c) {
        const double mph = in_us["results"][k]["vehicles"][i]["velocity"][c];
        const double ms = in_si["results"][k]["vehicles"][i]["velocity"][c];
        CHECK(std::abs(ms - mph * 0.44704) <= 4 * eps * (std::abs(ms) + 1e-300));
        const double degs = in_us["results"][k]["vehicles"][i]["yaw_rate_after"];
        const double rads = in_si["results"][k]["vehicles"][i]["yaw_rate_after"];
        CHECK(std::abs(rads - degs * M_PI / 180) <= 4 * eps * (std::abs(rads) + 1e-300));
        ++compared;
      }
  CHECK(compared == static_cast<int>(in_us["results"].size()) * 6);
  CHECK(compared > 0);
}

}  // namespace exam_reconstruction
