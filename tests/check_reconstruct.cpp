// The reconstruction (io/reconstruct.hpp) against what is known without it:
// - round trip: seeded random collisions in 3D and in the planar limit are solved forward from known
//   speeds for every strategy and regime; their exact post-impact velocities, fed back as evidence,
//   give back the speeds and the regime;
// - noise of known sd added to Figure 8's evidence over seeded trials: the spread of the estimates is
//   the reported standard error, within its sampling error, and chi2 averages its degrees of freedom;
// - a set-up whose evidence cannot determine the speeds (a central, collinear, perfectly plastic
//   impact: only the momentum is left) is reported unidentifiable along the combination derived by
//   hand; contradictory evidence fails the chi2 test.
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "impact3d/io/read_evidence.hpp"
#include "impact3d/io/reconstruct.hpp"
#include "impact3d/io/result_numbers.hpp"
#include "support.hpp"

namespace {

using namespace impact3d;
using namespace impact3d::io;
constexpr double kEps = 0x1p-52;

// A random collision as a case file: products of inertia, pitch, roll, a tilted contact frame and
// vertical velocities in 3D; none of them in the planar limit.
std::string random_case(std::mt19937_64& g, bool planar, const std::string& strategy) {
  std::uniform_real_distribution<double> u(0, 1);
  auto in = [&](double a, double b) { return a + (b - a) * u(g); };
  auto tilt = [&](double most) { return planar ? 0.0 : in(-most, most); };
  std::string vehicles;
  for (int i = 0; i < 2; ++i) {
    const double ixx = in(300, 1500), iyy = in(1200, 6000), izz = iyy + in(0.5, 1.0) * ixx;
    const double ixy = in(-0.1, 0.1) * ixx, ixz = tilt(0.1) * ixx, iyz = tilt(0.1) * ixx;
    vehicles += fmt::format(
        R"({}{{"mass": {:.17g}, "inertia": [[{:.17g}, {:.17g}, {:.17g}], [{:.17g}, {:.17g}, {:.17g}], [{:.17g}, {:.17g}, {:.17g}]],
        "orientation_deg": {{"yaw": {:.17g}, "pitch": {:.17g}, "roll": {:.17g}}},
        "velocity": [{:.17g}, {:.17g}, {:.17g}], "angular_velocity": [{:.17g}, {:.17g}, {:.17g}],
        "impulse_center": [{:.17g}, {:.17g}, {:.17g}]}})",
        i ? ", " : "", in(700, 3500), ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz, in(-180, 180), tilt(10), tilt(10), in(-25, 25),
        in(-25, 25), tilt(1), tilt(0.3), tilt(0.3), in(-1.5, 1.5), in(-2.6, 2.6), in(-1, 1), tilt(0.4));
  }
  return fmt::format(R"({{"units": "SI", "vehicles": [{}],
    "contact": {{"normal_yaw_deg": {:.17g}, "normal_pitch_deg": {:.17g}, "tangent_roll_deg": {:.17g}}},
    "restitution": {:.17g}, "strategy": {}}})",
                     vehicles, in(-180, 180), tilt(25), tilt(30), in(0, 0.6), strategy);
}

// The case's result at double: its numbers as the document writes them (result_numbers.hpp).
struct Forward {
  Regime regime;
  std::vector<double> numbers;
  double speed[2];
};

Forward forward_spec(const CaseSpec& spec) {
  const Scene<double> scene = to_scene<double>(spec);
  const Analysis<double> a = analyze(scene, to_strategies<double>(spec), Engine::generated);
  Forward f;
  f.regime = a.solutions.front().impulse.regime;
  f.numbers.resize(monte_carlo_outputs().size());
  std::vector<char> written(f.numbers.size());
  numbers_of_solution(a.solutions.front(), unit_factors<double>(spec.units), f.numbers.data(), written.data());
  for (std::size_t i = 0; i < 2; ++i) f.speed[i] = scene.body[i].v_W.norm();
  return f;
}

// None where the case does not approach or has no solution.
std::optional<Forward> forward(const std::string& text) {
  try {
    return forward_spec(read_case(text));
  } catch (const CaseError&) {
    return std::nullopt;
  } catch (const SolveError&) {
    return std::nullopt;
  }
}

// Figure 8 with its second strategy alone (pc-crash, mu 0.4: sliding), and that strategy.
std::pair<std::string, ReconstructOptions> figure8() {
  std::pair<std::string, ReconstructOptions> out;
  out.first = impact3d::test::read_text(impact3d::test::example("fig8_side_impact.json"));
  out.second.strategy = read_case(out.first).strategies[1];
  return out;
}

Forward forward_with(const std::string& text, const StrategySpec& strategy) {
  CaseSpec spec = read_case(text);
  spec.strategies = {strategy};
  return forward_spec(spec);
}

std::size_t output_index(const std::string& name) {
  const auto& all = monte_carlo_outputs();
  for (std::size_t c = 0; c < all.size(); ++c)
    if (all[c].text == name) return c;
  FAIL("no output " << name);
  return 0;
}

// Evidence: both vehicles' post-impact velocities and angular velocities as `f` has them (plus `shift`
// on vehicle 1's x velocity), with sd `sd_v` and `sd_w`.
std::string velocity_evidence(const Forward& f, double start0, double start1, double sd_v, double sd_w, double shift = 0) {
  std::string items;
  for (int i = 0; i < 2; ++i)
    for (const char* group : {"velocity", "angular_velocity"}) {
      std::vector<double> v;
      for (int k = 0; k < 3; ++k) v.push_back(f.numbers[output_index(fmt::format("vehicles[{}].{}[{}]", i, group, k))]);
      if (i == 1 && group == std::string("velocity")) v[0] += shift;
      items += fmt::format(R"({}{{"output": "vehicles[{}].{}", "value": [{:.17g}, {:.17g}, {:.17g}], "sd": {}}})",
                           items.empty() ? "" : ", ", i, group, v[0], v[1], v[2], group == std::string("velocity") ? sd_v : sd_w);
    }
  return fmt::format(R"({{"unknowns": [{{"speed": 0, "start": {:.17g}}}, {{"speed": 1, "start": {:.17g}}}], "evidence": [{}]}})", start0,
                     start1, items);
}

// The bound on a recovered speed when the evidence is the model's own output: the output's rounding
// (taken as 2^13 eps of the largest output, the verification suite's agreement with 100 digits being
// 1e-12 absolute on speeds of order 10) moves the fit by at most sd_j |delta r| (Cauchy-Schwarz on the
// least-squares solution J+ delta r, whose row j has length sd_j), plus the speed's own rounding.
double recovery_bound(const Fit& fit, std::size_t j, double min_sd, std::size_t m) {
  double scale = 0;
  for (const auto& r : fit.residuals) scale = std::max(scale, std::fabs(r.value));
  const double delta_r = std::sqrt(static_cast<double>(m)) * 0x1p13 * kEps * scale / min_sd;
  return fit.sd[j] * delta_r + 4 * kEps * std::fabs(fit.value[j]);
}

}  // namespace

TEST_CASE("round trip: exact post-impact velocities give back the speeds, for every strategy and regime, in 3D and planar") {
  const std::vector<std::pair<std::string, std::string>> strategies{
      {R"({"name": "pc-crash", "mu": 0.1})", "pc-crash"}, {R"({"name": "pc-crash", "mu": 3})", "pc-crash"},
      {R"({"name": "wach", "mu": 0.1, "limit": "cir"})", "wach"}, {R"({"name": "wach", "mu": 3, "limit": "gir"})", "wach"},
      {R"({"name": "brach", "mu_t": "critical", "mu_z": "critical"})", "brach"}};
  std::mt19937_64 g(20261125);
  std::map<std::string, int> checked;  // by "planar|3D strategy regime"
  int cases = 0;
  double worst = 0;  // the largest error in units of its bound
  for (const bool planar : {false, true})
    for (int n = 0; n < 12;) {
      const std::string probe = random_case(g, planar, strategies.front().first);
      if (!forward(probe)) continue;
      ++n, ++cases;
      for (const auto& [strategy, name] : strategies) {
        // The same collision with each strategy: only the strategy's text differs.
        std::string text = probe;
        text.replace(text.rfind(strategies.front().first), strategies.front().first.size(), strategy);
        const auto f = forward(text);
        if (!f) continue;  // counted below: every regime must still be reached
        // Starts 20 % off each way, the first that approaches (the reconstruction refuses a start with no
        // solution, naming it).
        std::optional<Reconstruction> fitted;
        for (const auto& [a, b] : {std::pair{0.8, 1.2}, {1.2, 0.8}, {0.8, 0.8}, {1.2, 1.2}})
          try {
            fitted = reconstruct(text, read_evidence(velocity_evidence(*f, a * f->speed[0], b * f->speed[1], 0.1, 0.01)), {});
            break;
          } catch (const CaseError& e) {
            REQUIRE_THAT(e.what(), Catch::Contains("starting values"));
          }
        if (!fitted) continue;
        const Reconstruction& r = *fitted;
        INFO(text);
        CHECK(r.best.regime == regime_name(f->regime));
        CHECK(r.best.admissible);
        CHECK(r.best.converged);
        REQUIRE(r.best.identifiable);
        CHECK(r.best.chi2 < 1e-12);
        for (std::size_t j = 0; j < 2; ++j) {
          const double bound = recovery_bound(r.best, j, 0.01, r.best.residuals.size());
          const double error = std::fabs(r.best.value[j] - f->speed[j]);
          CHECK(error <= bound);
          worst = std::max(worst, error / bound);
        }
        ++checked[fmt::format("{} {} {}", planar ? "planar" : "3D", name, r.best.regime)];
      }
    }
  std::string summary;
  for (const auto& [k, count] : checked) summary += fmt::format("{}: {}; ", k, count);
  INFO(summary << " worst error " << worst << " of its bound");
  CHECK(cases == 24);
  for (const char* kind : {"3D", "planar"})
    for (const char* regime : {"pc-crash full", "pc-crash sliding", "wach capped", "wach sliding", "brach as-given"})
      CHECK(checked[fmt::format("{} {}", kind, regime)] >= 2);
}

TEST_CASE("noise of known sd: the estimates spread as their reported standard errors, and chi2 averages its dof") {
  const auto [text, o] = figure8();
  const Forward f = forward_with(text, *o.strategy);
  REQUIRE(f.regime == Regime::sliding);
  constexpr int kTrials = 300;
  constexpr double kSdV = 0.3, kSdW = 0.05;
  std::mt19937_64 g(42);
  std::normal_distribution<double> noise(0, 1);
  std::vector<double> estimates[2];
  double reported_sd[2] = {0, 0}, chi2_sum = 0;
  std::size_t dof = 0;
  int trials = 0;
  for (int t = 0; t < kTrials; ++t) {
    Forward noisy = f;
    for (int i = 0; i < 2; ++i)
      for (const char* group : {"velocity", "angular_velocity"})
        for (int k = 0; k < 3; ++k)
          noisy.numbers[output_index(fmt::format("vehicles[{}].{}[{}]", i, group, k))] +=
              (group == std::string("velocity") ? kSdV : kSdW) * noise(g);
    const Reconstruction r = reconstruct(text, read_evidence(velocity_evidence(noisy, 10, 10, kSdV, kSdW)), o);
    REQUIRE(r.best.identifiable);
    REQUIRE(r.best.converged);
    for (int j = 0; j < 2; ++j) {
      estimates[j].push_back(r.best.value[static_cast<std::size_t>(j)]);
      reported_sd[j] += r.best.sd[static_cast<std::size_t>(j)] / kTrials;
    }
    chi2_sum += r.best.chi2;
    dof = r.best.dof;
    ++trials;
  }
  REQUIRE(trials == kTrials);
  for (int j = 0; j < 2; ++j) {
    double mean = 0, var = 0;
    for (double x : estimates[j]) mean += x / kTrials;
    for (double x : estimates[j]) var += (x - mean) * (x - mean) / (kTrials - 1);
    const double spread = std::sqrt(var);
    INFO("speed " << j << ": mean " << mean << " (true " << f.speed[j] << "), spread " << spread << ", reported sd " << reported_sd[j]);
    // The sample sd of n normal values has a relative standard error of 1/sqrt(2(n - 1)): 4.1 % at
    // n = 300; four of them, plus 3 % for the model's curvature over the noise (sliding is not linear
    // in the speeds).
    CHECK(std::fabs(spread / reported_sd[j] - 1) < 4 / std::sqrt(2.0 * (kTrials - 1)) + 0.03);
    // The mean within four of its standard errors, plus the same curvature's bias.
    CHECK(std::fabs(mean - f.speed[j]) < 4 * reported_sd[j] / std::sqrt(double(kTrials)) + 0.03 * reported_sd[j]);
  }
  // chi2 of a correct linearized model averages dof, with a standard error sqrt(2 dof / n).
  const double mean_chi2 = chi2_sum / kTrials;
  INFO("mean chi2 " << mean_chi2 << " with " << dof << " degrees of freedom");
  CHECK(dof == 10);  // 12 components, two unknowns
  CHECK(std::fabs(mean_chi2 - double(dof)) < 4 * std::sqrt(2.0 * dof / kTrials) + 0.03 * dof);
}

TEST_CASE("a central collinear plastic impact leaves m1 speed0 + m0 speed1 undetermined, and contradictory evidence fails chi2") {
  // Vehicle 1 (mass m0) heads +x, vehicle 2 (m1) heads -x, both impulse centres at the CGs on the x
  // axis, restitution 0: a Full Impact leaves both at the common velocity (m0 s0 - m1 s1) / (m0 + m1),
  // so only the momentum is known, and (s0, s1) + t (m1, m0) changes nothing (hand derivation).
  const double m0 = 1500, m1 = 2100;
  std::string text;
  for (const char* yaw : {"0", "180"}) {
    text = fmt::format(R"({{"units": "SI", "vehicles": [
      {{"mass": {}, "inertia": {{"Ixx": 500, "Iyy": 2500, "Izz": 2700}}, "orientation_deg": {{"yaw": 0}},
        "velocity": [12, 0, 0], "impulse_center": [0, 0, 0]}},
      {{"mass": {}, "inertia": {{"Ixx": 700, "Iyy": 3500, "Izz": 3800}}, "orientation_deg": {{"yaw": 180}},
        "velocity": [-9, 0, 0], "impulse_center": [0, 0, 0]}}],
      "contact": {{"normal_yaw_deg": {}}}, "restitution": 0, "strategy": {{"name": "pc-crash", "mu": 1}}}})",
                       m0, m1, yaw);
    if (forward(text)) break;
  }
  const auto f = forward(text);
  REQUIRE(f);
  REQUIRE(f->regime == Regime::full);
  const Reconstruction r = reconstruct(text, read_evidence(velocity_evidence(*f, 10, 10, 0.1, 0.01)), {});
  CHECK_FALSE(r.best.identifiable);
  REQUIRE(r.best.undetermined.size() == 1);
  const auto& c = r.best.undetermined.front().combination;
  const double norm = std::hypot(m0, m1);
  // The combination's rounding: the Jacobian's entries to a few ulps, through the SVD (2^10 eps).
  CHECK(std::fabs(c[0] - m1 / norm) < 0x1p10 * kEps);
  CHECK(std::fabs(c[1] - m0 / norm) < 0x1p10 * kEps);
  CHECK(std::isnan(r.best.value[0]));
  CHECK(std::isnan(r.best.value[1]));
  CHECK(std::isnan(r.best.sd[0]));

  // Figure 8 with vehicle 2's x velocity 3 m/s (30 sd) off: chi2 of order 900 on 10 degrees of freedom.
  const auto [fig8, o] = figure8();
  const Forward fw = forward_with(fig8, *o.strategy);
  const Reconstruction bad = reconstruct(fig8, read_evidence(velocity_evidence(fw, 10, 10, 0.1, 0.01, 3.0)), o);
  CHECK(bad.best.identifiable);
  CHECK(bad.best.chi2 > 100);
  CHECK(bad.best.p_value < 1e-6);
  const Reconstruction good = reconstruct(fig8, read_evidence(velocity_evidence(fw, 10, 10, 0.1, 0.01)), o);
  CHECK(good.best.p_value > 0.99);
}
