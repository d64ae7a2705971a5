// The reconstruction (studies/reconstruct.hpp) against what is known without it:
// - round trip: seeded random collisions in 3D and in the planar limit are solved forward from known
//   speeds for every strategy and regime; their exact post-impact velocities, fed back as evidence,
//   give back the speeds and the regime, and the reported sd equal those of a Jacobian by central
//   differences of the forward solve; so do headings, restitution and a product of inertia on Figure 8;
// - noise of known sd added to a linear (Full Impact) model's evidence over seeded trials: the spread
//   of the estimates is the reported standard error, within its sampling error, and chi2 averages its
//   degrees of freedom;
// - a set-up whose evidence cannot determine the speeds (a central, collinear, perfectly plastic
//   impact: only the momentum is left) is reported unidentifiable along the combination derived by
//   hand; contradictory evidence fails the chi2 test;
// - two regimes that both fit are both reported, a fit on the kink between regimes and a fit held at
//   the edge of what the case accepts are flagged, each checked by forward solves of its own; angles
//   wrap; a known speed is the unknown itself.
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "impact3d/case_format/read_evidence.hpp"
#include "impact3d/studies/reconstruct.hpp"
#include "impact3d/studies/result_numbers.hpp"
#include "impact3d/case_format/strategy_option.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "support.hpp"

namespace check_reconstruct {

namespace {

using namespace impact3d;
using namespace impact3d::case_format;
using namespace impact3d::studies;
constexpr double kEps = 0x1p-52;

// Uniform in [0, 1) and standard normal draws from the generator's bits, the same on every standard
// library (its distributions are not): the counts below hold everywhere.
double uniform01(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1p-53; }
double normal01(std::mt19937_64& g) {  // Box-Muller
  const double u = 1 - uniform01(g), v = uniform01(g);
  return std::sqrt(-2 * std::log(u)) * std::cos(2 * std::acos(-1.0) * v);
}

// A random collision as a case file: products of inertia, pitch, roll, a tilted contact frame and
// vertical velocities in 3D; none of them in the planar limit.
std::string random_case(std::mt19937_64& g, bool planar, const std::string& strategy) {
  auto in = [&](double a, double b) { return a + (b - a) * uniform01(g); };
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

StrategySpec read_case_strategy(const std::string& option) { return read_strategy_option(option, 0); }

// Figure 8 with one of its strategies alone (by default the second: pc-crash, mu 0.4, sliding), and
// that strategy.
std::pair<std::string, ReconstructOptions> figure8(std::size_t strategy = 1) {
  std::pair<std::string, ReconstructOptions> out;
  out.first = impact3d::test::read_text(impact3d::test::example("fig8_side_impact.json"));
  out.second.strategy = read_case(out.first).strategies[strategy];
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

// The speeds' standard errors from a Jacobian by central differences of the forward solve (no dual
// numbers): sqrt(diag((J^T W J)^-1)) over velocity_evidence's components (sd 0.1 and 0.01). None where a
// step changes the regime. A relative step h = 1e-6 leaves a truncation error of order h^2 = 1e-12 and
// a rounding error of order 2^4 eps / h = 4e-9 of each derivative's scale.
struct Differences {
  std::array<double, 2> sd;
  double condition;  // of J^T W J
};
std::optional<Differences> sd_by_differences(const std::string& text, const Forward& f) {
  constexpr double h = 1e-6;
  const CaseSpec base = read_case(text);
  Eigen::MatrixXd J(12, 2);
  for (int i = 0; i < 2; ++i) {
    std::array<std::vector<double>, 2> at;
    for (int side = 0; side < 2; ++side) {
      CaseSpec spec = base;
      for (auto& n : spec.vehicles[static_cast<std::size_t>(i)].velocity) {
        n.value *= side ? 1 - h : 1 + h;
        n.text = fmt::format("{:.17g}", n.value);
      }
      const Forward moved = forward_spec(spec);
      if (moved.regime != f.regime) return std::nullopt;
      at[static_cast<std::size_t>(side)] = moved.numbers;
    }
    int row = 0;
    for (int v = 0; v < 2; ++v)
      for (const char* group : {"velocity", "angular_velocity"})
        for (int k = 0; k < 3; ++k, ++row) {
          const std::size_t c = output_index(fmt::format("vehicles[{}].{}[{}]", v, group, k));
          J(row, i) = (at[0][c] - at[1][c]) / (2 * h * f.speed[i]) / (group == std::string("velocity") ? 0.1 : 0.01);
        }
  }
  const Eigen::Matrix2d A = J.transpose() * J;
  const Eigen::Matrix2d C = A.inverse();
  const Eigen::Vector2d lambda = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(A).eigenvalues();
  return Differences{{std::sqrt(C(0, 0)), std::sqrt(C(1, 1))}, lambda[1] / lambda[0]};
}

// The bound on a recovered speed when the evidence is the model's own output: the output's rounding
// (taken as 2^13 eps of the largest output, the verification suite's agreement with 100 digits being
// 1e-12 absolute on speeds of order 10) moves the fit by at most sd_j |delta r| (Cauchy-Schwarz on the
// least-squares solution J+ delta r, whose row j has length sd_j, here from differences), plus the
// speed's own rounding.
double recovery_bound(const Fit& fit, double sd, double min_sd, std::size_t m, double value) {
  double scale = 0;
  for (const auto& r : fit.residuals) scale = std::max(scale, std::fabs(r.value));
  const double delta_r = std::sqrt(static_cast<double>(m)) * 0x1p13 * kEps * scale / min_sd;
  return sd * delta_r + 4 * kEps * std::fabs(value);
}

}  // namespace

TEST_CASE("round trip: exact post-impact velocities give back the speeds, for every strategy and regime, in 3D and planar") {
  const std::vector<std::pair<std::string, std::string>> strategies{
      {R"({"name": "pc-crash", "mu": 0.1})", "pc-crash"}, {R"({"name": "pc-crash", "mu": 3})", "pc-crash"},
      {R"({"name": "wach", "mu": 0.1, "limit": "cir"})", "wach"}, {R"({"name": "wach", "mu": 3, "limit": "gir"})", "wach"},
      {R"({"name": "brach", "mu_t": "critical", "mu_z": "critical"})", "brach"}};
  std::mt19937_64 g(20261125);
  std::map<std::string, int> checked;  // by "planar|3D strategy regime"
  int cases = 0, sds = 0;
  double worst = 0, worst_sd = 0;  // the largest error in units of its bound; the largest sd's relative error
  for (const bool planar : {false, true})
    for (int n = 0, tries = 0; n < 12 && tries < 1000; ++tries) {
      const std::string probe = random_case(g, planar, strategies.front().first);
      if (!forward(probe)) continue;  // not approaching
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
        const auto sd = sd_by_differences(text, *f);
        if (!sd) continue;  // a step of 1e-6 switched the regime: no differences there
        ++sds;
        // The differences' error, of order 4e-9 of each derivative, amplified by at most twice the
        // condition of J^T W J in its inverse and halved by the square root; the order of magnitude
        // allowed five times over: 2e-8 times the condition, of each sd.
        for (std::size_t j = 0; j < 2; ++j) {
          CHECK(std::fabs(r.best.sd[j] - sd->sd[j]) <= 2e-8 * sd->condition * sd->sd[j]);
          worst_sd = std::max(worst_sd, std::fabs(r.best.sd[j] / sd->sd[j] - 1));
          const double bound = recovery_bound(r.best, sd->sd[j], 0.01, r.best.residuals.size(), f->speed[j]);
          const double error = std::fabs(r.best.value[j] - f->speed[j]);
          CHECK(error <= bound);
          worst = std::max(worst, error / bound);
        }
        ++checked[fmt::format("{} {} {}", planar ? "planar" : "3D", name, r.best.regime)];
      }
    }
  std::string summary;
  for (const auto& [k, count] : checked) summary += fmt::format("{}: {}; ", k, count);
  INFO(summary << " worst error " << worst << " of its bound; sd within " << worst_sd << " of the differences'");
  CHECK(cases == 24);
  CHECK(sds >= 100);
  for (const char* kind : {"3D", "planar"})
    for (const char* regime : {"pc-crash full", "pc-crash sliding", "wach capped", "wach sliding", "brach as-given"})
      CHECK(checked[fmt::format("{} {}", kind, regime)] >= 2);
}

TEST_CASE("round trip with headings, restitution and a product of inertia unknown: Figure 8 changed is recovered") {
  // The truth: the Malibu at 12 m/s turned 5 degrees left of +x, the Suburban at 10 m/s turned 3
  // degrees right of +y, restitution 0.3, the Malibu's I_xz -60 (both entries). The case given to the
  // fit keeps Figure 8's directions, restitution 0.1 and I_xz -40: the headings are deviations from
  // those directions, in heading_after_deg's sense; I_xz's mirror moves with it.
  const auto figure = figure8();  // not bound as [text, o]: a lambda below reads text, which clang 14 cannot capture
  const std::string& text = figure.first;
  const ReconstructOptions& o = figure.second;
  auto replaced = [](std::string t, const std::string& from, const std::string& to) {
    const std::size_t at = t.find(from);
    REQUIRE(at != std::string::npos);
    return t.replace(at, from.size(), to);
  };
  const double deg = std::acos(-1.0) / 180;
  // The case at (s0, s1, d0, d1, e, I_xz), written as text.
  auto truth = [&](const std::array<double, 6>& p) {
    std::string t = replaced(text, "[11.176, 0, 0]", fmt::format("[{:.17g}, {:.17g}, 0]", p[0] * std::cos(p[2] * deg), p[0] * std::sin(p[2] * deg)));
    t = replaced(t, "[0, 11.176, 0]", fmt::format("[{:.17g}, {:.17g}, 0]", -p[1] * std::sin(p[3] * deg), p[1] * std::cos(p[3] * deg)));
    t = replaced(t, "\"restitution\": 0.1", fmt::format("\"restitution\": {:.17g}", p[4]));
    return replaced(t, "[[560, 0, -40], [0, 2500, 0], [-40, 0, 2700]]",
                    fmt::format("[[560, 0, {0:.17g}], [0, 2500, 0], [{0:.17g}, 0, 2700]]", p[5]));
  };
  const std::array<double, 6> expected{12, 10, 5, -3, 0.3, -60};
  const Forward f = forward_with(truth(expected), *o.strategy);
  std::string evidence = velocity_evidence(f, 11, 11, 0.1, 0.01);
  evidence = replaced(evidence, "{\"speed\": 1, \"start\": 11}",
                      "{\"speed\": 1, \"start\": 11}, {\"heading\": 0}, {\"heading\": 1}, {\"path\": \"$.restitution\"}, "
                      "{\"path\": \"$.vehicles[0].inertia[2][0]\"}");  // the mirror's path: the same input
  const Reconstruction r = reconstruct(text, read_evidence(evidence), o);
  REQUIRE(r.best.identifiable);
  CHECK(r.best.regime == regime_name(f.regime));
  // The standard errors from central differences of the forward solve through the case text (relative
  // steps of 1e-6, as sd_by_differences): they check the chain rule through speeds and headings, and
  // they bound the recovery independently of the sd under test.
  Eigen::MatrixXd J(12, 6);
  for (std::size_t j = 0; j < 6; ++j) {
    const double h = 1e-6 * std::max(std::fabs(expected[j]), 1.0);
    std::array<double, 6> up = expected, down = expected;
    up[j] += h, down[j] -= h;
    const Forward a = forward_with(truth(up), *o.strategy), b = forward_with(truth(down), *o.strategy);
    REQUIRE(a.regime == f.regime);
    REQUIRE(b.regime == f.regime);
    int row = 0;
    for (int v = 0; v < 2; ++v)
      for (const char* group : {"velocity", "angular_velocity"})
        for (int k = 0; k < 3; ++k, ++row) {
          const std::size_t c = output_index(fmt::format("vehicles[{}].{}[{}]", v, group, k));
          J(row, static_cast<Eigen::Index>(j)) = (a.numbers[c] - b.numbers[c]) / (2 * h) / (group == std::string("velocity") ? 0.1 : 0.01);
        }
  }
  const Eigen::MatrixXd A = J.transpose() * J;
  const Eigen::MatrixXd C = A.inverse();
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues();
  const double condition = lambda[5] / lambda[0];
  for (std::size_t j = 0; j < 6; ++j) {
    const double sd = std::sqrt(C(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j)));
    INFO(r.unknowns[j].label() << " = " << r.best.value[j] << " sd " << r.best.sd[j] << ", expected " << expected[j] << " sd " << sd
                               << " (condition " << condition << ")");
    // As in the round trip: 2e-8 times the condition, of each sd.
    CHECK(std::fabs(r.best.sd[j] - sd) <= 2e-8 * condition * sd);
    // The truth's inputs pass through 17 digits, cos and sin: a few ulps, as the outputs' own rounding
    // that recovery_bound allows for.
    CHECK(std::fabs(r.best.value[j] - expected[j]) <= recovery_bound(r.best, sd, 0.01, r.best.residuals.size(), expected[j]));
  }
}

TEST_CASE("a PDOF across 0/360 and a known speed: residuals wrap, and the thread's imposed branch and seeds are the caller's again") {
  const auto [text, o] = figure8();
  const Forward f = forward_with(text, *o.strategy);
  const double pdof = f.numbers[output_index("vehicles[1].pdof_deg")];
  REQUIRE(pdof > 300);  // 338 degrees: given as its equal below 0
  std::string evidence = velocity_evidence(f, 10, 10, 0.1, 0.01);
  evidence.insert(evidence.rfind("]}"), fmt::format(R"(, {{"output": "vehicles[1].pdof_deg", "value": {:.17g}, "sd": 2}},
      {{"speed": 0, "value": {:.17g}, "sd": 0.1}})", pdof - 360, f.speed[0]));
  const Reconstruction r = reconstruct(text, read_evidence(evidence), o);
  REQUIRE(r.best.residuals.size() == 14);
  const EvidenceResidual& angle = r.best.residuals[12];
  CHECK(angle.output == "vehicles[1].pdof_deg");
  // The fit is the truth to its recovery bound (~1e-9 m/s here): the angle's residual is that small,
  // not 360 degrees.
  CHECK(std::fabs(angle.residual) < 1e-6);
  const EvidenceResidual& speed = r.best.residuals[13];
  CHECK(speed.output == "speed[0]");
  CHECK(std::fabs(speed.fitted - r.best.value[0]) <= 4 * kEps * speed.fitted);  // the speed evidence is the unknown itself
  CHECK(r.best.chi2 < 1e-12);
  // A caller's own imposed branch and seeds are what the thread holds after a fit, and after a fit
  // refused (a start the case cannot solve, named with the starts).
  const ImposedBranch outer_branch{decision_names::volume, true};
  const DualSeeds outer_seeds;
  const ImposeBranch impose(&outer_branch);
  const DualSeedScope seed(outer_seeds);
  (void)reconstruct(text, read_evidence(evidence), o);
  CHECK(ImposedBranch::current == &outer_branch);
  CHECK(dual_seeds == &outer_seeds);
  std::string bad = velocity_evidence(f, 10, -30, 0.1, 0.01);
  CHECK_THROWS_WITH(reconstruct(text, read_evidence(bad), o),
                    Catch::StartsWith("the case has no solution at the unknowns' starting values (speed[0] = 10, speed[1] = -30)"));
  CHECK(ImposedBranch::current == &outer_branch);
  CHECK(dual_seeds == &outer_seeds);
}

TEST_CASE("two regimes that both fit are both reported, and a fit on the regime boundary is flagged") {
  // Figure 8 at pc-crash mu = GIR - 0.019 (0.46), just below its GIR: sliding at the case's speeds. The
  // Malibu's Delta-V there, as the only evidence on its speed, is met twice: by the case's speed in
  // sliding, and by another speed in a Full Impact (found by a search over Figure 8; each checked below
  // by a forward solve of its own).
  auto [text, o] = figure8();
  const double gir = forward_with(text, *o.strategy).numbers[output_index("limits.gir")];
  o.strategy = read_case_strategy(fmt::format("pc-crash:mu={:.17g}", gir - 0.019));
  const Forward f = forward_with(text, *o.strategy);
  REQUIRE(f.regime == Regime::sliding);
  const double dv = f.numbers[output_index("vehicles[0].delta_v_magnitude")];
  const Reconstruction r = reconstruct(
      text, read_evidence(fmt::format(R"({{"unknowns": [{{"speed": 0}}], "evidence": [{{"output": "vehicles[0].delta_v_magnitude", "value": {:.17g}, "sd": 0.05}}]}})", dv)), o);
  REQUIRE(r.alternatives.size() == 1);
  std::map<std::string, const Fit*> by_regime{{r.best.regime, &r.best}, {r.alternatives[0].regime, &r.alternatives[0]}};
  REQUIRE(by_regime.count("full"));
  REQUIRE(by_regime.count("sliding"));
  CHECK(r.inadmissible.empty());
  for (const auto& [regime, fit] : by_regime) {
    INFO(regime << ": speed " << fit->value[0]);
    CHECK(fit->admissible);
    CHECK(fit->converged);
    CHECK(fit->chi2 < 1e-12);
    // The case at the fitted speed, solved forward on its own: this regime, and this Delta-V.
    std::string at = text;
    at.replace(at.find("[11.176, 0, 0]"), 14, fmt::format("[{:.17g}, 0, 0]", fit->value[0]));
    const Forward g = forward_with(at, *o.strategy);
    CHECK(regime_name(g.regime) == regime);
    // The fit's own residual (chi2 < 1e-12: below 1e-6 sd) and the outputs' rounding (2^13 eps, as
    // recovery_bound): the forward solve is double arithmetic, the fit's dual numbers.
    CHECK(std::fabs(g.numbers[output_index("vehicles[0].delta_v_magnitude")] - dv) <= 1e-6 * 0.05 + 0x1p13 * kEps * dv);
  }
  CHECK(std::fabs(by_regime["sliding"]->value[0] - f.speed[0]) <= 1e-9 * f.speed[0]);
  CHECK(std::fabs(by_regime["full"]->value[0] - f.speed[0]) > 0.1);

  // The same Delta-V at mu = GIR - 0.059 (0.42): the Full Impact's least squares now lies where the inputs decide
  // sliding and the sliding one's where they decide a Full Impact, so the whole model's least is on the
  // boundary, a kink (found by the same search). A step of 0.1 % either way from it changes the regime.
  ReconstructOptions low = o;
  low.strategy = read_case_strategy(fmt::format("pc-crash:mu={:.17g}", gir - 0.059));
  const Reconstruction k = reconstruct(
      text, read_evidence(fmt::format(R"({{"unknowns": [{{"speed": 0}}], "evidence": [{{"output": "vehicles[0].delta_v_magnitude", "value": {:.17g}, "sd": 0.05}}]}})", dv)), low);
  CHECK_FALSE(k.best.admissible);
  REQUIRE_FALSE(k.best.warnings.empty());
  CHECK_THAT(k.best.warnings.front(), Catch::StartsWith("no regime's fit lies in its own regime: this fit of the whole model is on or near the boundary"));
  REQUIRE(k.inadmissible.size() == 2);
  for (const Fit& fit : k.inadmissible) {
    CHECK(fit.converged);
    CHECK(fit.decided != fit.imposed);
  }
  std::set<std::string> regimes;
  for (const double side : {0.999, 1.001}) {
    std::string at = text;
    at.replace(at.find("[11.176, 0, 0]"), 14, fmt::format("[{:.17g}, 0, 0]", k.best.fitted[0] * side));
    regimes.insert(regime_name(forward_with(at, *low.strategy).regime));
  }
  CHECK(regimes.size() == 2);
}

TEST_CASE("a fit held at the edge of what the case accepts is not converged, not admitted and not tested") {
  // Figure 8's Full Impact has an effective restitution equal to e, which the case bounds by 1: evidence
  // of 1.3 pushes e against that edge, where the minimizer's steps are refused.
  const auto [text, o] = figure8(0);
  const Reconstruction r = reconstruct(
      text,
      read_evidence(R"({"unknowns": [{"path": "$.restitution", "start": 0.5}],
                        "evidence": [{"output": "impulse_space.restitution_effective", "value": 1.3, "sd": 0.01}]})"),
      o);
  CHECK_FALSE(r.best.converged);
  CHECK_FALSE(r.best.admissible);
  CHECK_THAT(r.best.solver_status, Catch::StartsWith("stopped at the edge of the inputs the case accepts"));
  CHECK(r.alternatives.empty());
  CHECK_THAT(reconstruction_json(r), Catch::Contains(R"("chi2_test": "untested")"));
  CHECK(std::fabs(r.best.fitted[0] - 1) < 1e-6);

  // The Malibu's Delta-V and the Suburban's yaw rate for two speeds (no degrees of freedom; the two
  // Delta-Vs would not do: equal and opposite impulses keep their ratio at the masses'), from starts far
  // off: an exact fit, converged and admitted, whatever steps the case refused on the way.
  const auto [text1, sliding] = figure8();
  const Forward f = forward_with(text1, *sliding.strategy);
  const Reconstruction exact = reconstruct(
      text1,
      read_evidence(fmt::format(R"({{"unknowns": [{{"speed": 0, "start": 30}}, {{"speed": 1, "start": 3}}],
          "evidence": [{{"output": "vehicles[0].delta_v_magnitude", "value": {:.17g}, "sd": 0.1}},
                       {{"output": "vehicles[1].angular_velocity[2]", "value": {:.17g}, "sd": 0.01}}]}})",
                                f.numbers[output_index("vehicles[0].delta_v_magnitude")],
                                f.numbers[output_index("vehicles[1].angular_velocity[2]")])),
      sliding);
  CHECK(exact.best.converged);
  CHECK(exact.best.admissible);
  CHECK(exact.best.identifiable);
  CHECK(exact.best.dof == 0);
  CHECK(exact.best.chi2 < 1e-12);
}

TEST_CASE("noise of known sd: the estimates spread as their reported standard errors, and chi2 averages its dof") {
  // Figure 8's Full Impact (pc-crash, mu 1: GIR 0.48 is far from mu): its post-impact velocities are
  // linear in the speeds (the impulse is linear in the relative velocity), so the least-squares
  // estimates are exactly normal with the reported covariance, unbiased, and chi2 is chi-squared.
  const auto [text, o] = figure8(0);
  const Forward f = forward_with(text, *o.strategy);
  REQUIRE(f.regime == Regime::full);
  constexpr int kTrials = 300;
  constexpr double kSdV = 0.3, kSdW = 0.05;
  std::mt19937_64 g(42);
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
              (group == std::string("velocity") ? kSdV : kSdW) * normal01(g);
    const Reconstruction r = reconstruct(text, read_evidence(velocity_evidence(noisy, 10, 10, kSdV, kSdW)), o);
    REQUIRE(r.best.identifiable);
    REQUIRE(r.best.converged);
    REQUIRE(r.best.regime == "full");
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
    // n = 300; within four of them.
    CHECK(std::fabs(spread / reported_sd[j] - 1) < 4 / std::sqrt(2.0 * (kTrials - 1)));
    // The mean within four of its standard errors.
    CHECK(std::fabs(mean - f.speed[j]) < 4 * reported_sd[j] / std::sqrt(double(kTrials)));
  }
  // chi2 of a linear model averages dof, with a standard error sqrt(2 dof / n).
  const double mean_chi2 = chi2_sum / kTrials;
  INFO("mean chi2 " << mean_chi2 << " with " << dof << " degrees of freedom");
  CHECK(dof == 10);  // 12 components, two unknowns
  CHECK(std::fabs(mean_chi2 - double(dof)) < 4 * std::sqrt(2.0 * dof / kTrials));
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

}  // namespace check_reconstruct
