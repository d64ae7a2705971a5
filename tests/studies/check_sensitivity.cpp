// The sensitivities (studies/sensitivity.hpp: forward-mode automatic differentiation on Eigen's
// AutoDiffScalar) against what is known without automatic differentiation:
// - central differences of the 100-digit solve, for every example, result, output and input: the step
//   h = 1e-20 max(|x|, 1) leaves a truncation error of order h^2 = 1e-40 and a rounding error of order
//   1e-99 / h = 1e-79, so the differences are exact to far below double's epsilon;
// - the two engines (generated kernels, direct 3x3 solve) against each other;
// - the regime margin against GIR - mu as `solve` writes them.
// An error is measured as the change of the output for a change of the input by its own size,
// |d_ad - d_cd| max(|x|, 1), relative to the output's scale (its value, and the largest such change by
// any input): the form in which rounding of the double computation shows.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "impact3d/case_format/case_numbers.hpp"
#include "impact3d/case_format/strategy_option.hpp"
#include "impact3d/studies/result_numbers.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/studies/sensitivity.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/mechanics/analysis.hpp"
#include "support.hpp"

namespace check_sensitivity {

namespace {

using namespace impact3d;
using namespace impact3d::case_format;
using namespace impact3d::studies;
using F = mp::float100;

const char* const kExamples[] = {"fig8_side_impact.json", "offset_frontal.json", "override_pickup_into_sedan_rear.json",
                                 "us_pickup_into_sedan.json"};

// Outputs of every result of the case at 100 digits (or G's), with input j moved by `step` (in the case's
// units).
template <typename G = F>
std::vector<std::vector<G>> outputs_at(const CaseSpec& base, std::size_t j, const G& step, Engine engine) {
  CaseSpec spec = base;
  CaseInputs in = case_inputs(spec);
  for (Number* n : in.inputs[j].numbers) {
    const G x = scalar_from_text<G>(n->text) + step;
    n->text = x.str(60, std::ios_base::scientific);
  }
  const Analysis<G> a = analyze(to_scene<G>(spec), to_strategies<G>(spec), engine);
  const UnitFactors<G> f = unit_factors<G>(spec.units);
  std::vector<std::vector<G>> out;
  for (const auto& sol : a.solutions) {
    std::vector<G> v(monte_carlo_outputs().size());
    std::vector<char> written(v.size());
    numbers_of_solution(sol, f, v.data(), written.data());
    for (std::size_t c = 0; c < v.size(); ++c)
      if (!written[c]) v[c] = std::numeric_limits<G>::quiet_NaN();
    out.push_back(std::move(v));
  }
  return out;
}

struct Worst {
  double error = 0;  // in units of double's epsilon
  std::string where;
  std::size_t compared = 0, skipped = 0;
};

// With `strategies` in place of the case's when not empty, differenced at G with steps of `step` times
// the input's size.
template <typename G = F>
void against_central_differences(const std::string& name, Engine engine, Worst& worst,
                                 const std::vector<StrategySpec>& strategies = {}, const char* step = "1e-20",
                                 double loud = 1024) {
  const std::string text = test::read_text(test::example(name));
  SensitivityOptions o;
  o.engine = engine;
  o.strategies = strategies;
  const SensitivityRun run = sensitivity(text, o);
  CaseSpec spec = read_case(text);
  if (!strategies.empty()) spec.strategies = strategies;
  CaseInputs in = case_inputs(spec);
  REQUIRE(in.inputs.size() == run.inputs.size());
  const std::size_t n = run.inputs.size(), outputs = monte_carlo_outputs().size();
  // cd[k][c][j] and the size of each input.
  std::vector<std::vector<std::vector<double>>> cd(run.results.size(), std::vector<std::vector<double>>(outputs, std::vector<double>(n)));
  std::vector<double> size(n);
  const auto at = outputs_at<G>(spec, 0, G(0), engine);
  for (std::size_t j = 0; j < n; ++j) {
    REQUIRE(in.inputs[j].path == run.inputs[j]);
    const G x = scalar_from_text<G>(in.inputs[j].numbers.front()->text);
    const G h = G(step) * std::max<G>(G(abs(x)), G(1));
    size[j] = std::max(std::fabs(static_cast<double>(x)), 1.0);
    const auto up = outputs_at<G>(spec, j, h, engine), down = outputs_at<G>(spec, j, G(-h), engine);
    for (std::size_t k = 0; k < run.results.size(); ++k)
      for (std::size_t c = 0; c < outputs; ++c) {
        G change = up[k][c] - down[k][c];
        // An angle is differenced on the circle: a swerve of 180 degrees (a reversed sliding) is +-180
        // by the sign of a rounding error at 100 digits.
        if (monte_carlo_outputs()[c].angle) change -= 360 * floor(G(change / 360 + G(0.5)));
        cd[k][c][j] = static_cast<double>(G(change / (2 * h)));
      }
  }
  const auto& names = monte_carlo_outputs();
  for (std::size_t k = 0; k < run.results.size(); ++k) {
    const auto& r = run.results[k];
    // Outputs that are zero throughout the regime (sliding after a Full Impact) are held to the scale
    // of the relative velocity they are part of.
    double velocity_scale = 0;
    for (std::size_t c = 0; c < outputs; ++c)
      if (names[c].text.rfind("relative_velocity.before", 0) == 0) velocity_scale = std::max(velocity_scale, std::fabs(r.values[c]));
    for (std::size_t c = 0; c < outputs; ++c) {
      if (!r.written[c]) continue;
      double scale = std::fabs(static_cast<double>(at[k][c]));
      bool defined = true;
      for (std::size_t j = 0; j < n; ++j) {
        defined = defined && std::isfinite(cd[k][c][j]);
        scale = std::max(scale, std::fabs(cd[k][c][j]) * size[j]);
      }
      if (!defined || !std::isfinite(r.values[c]) || !std::isfinite(scale)) {  // null at 100 digits (a swerve of no sliding): nothing to compare
        ++worst.skipped;
        continue;
      }
      if (scale < 1e-30) scale = velocity_scale;
      for (std::size_t j = 0; j < n; ++j) {
        const double ad = run.derivative(k, c, j);
        const double e = std::isfinite(ad) ? std::fabs(ad - cd[k][c][j]) * size[j] / scale / test::eps : 1e300;
        if (!(e <= loud)) WARN(name << " " << k << " " << names[c].text << " " << run.inputs[j] << " ad " << ad << " cd " << cd[k][c][j] << " scale " << scale);
        ++worst.compared;
        if (e > worst.error)
          worst.error = e, worst.where = name + " results[" + std::to_string(k) + "]." + names[c].text + " by " + run.inputs[j];
      }
    }
  }
}

}  // namespace

TEST_CASE("every derivative of every example agrees with 100-digit central differences") {
  for (Engine engine : {Engine::generated, Engine::direct}) {
    Worst worst;
    for (const char* name : kExamples) against_central_differences(name, engine, worst);
    INFO((engine == Engine::direct ? "direct" : "generated") << ": worst " << worst.error << " eps at " << worst.where
                                                              << " (" << worst.compared << " compared, " << worst.skipped << " skipped)");
    CHECK(worst.compared > 4 * 40 * 40);
    // The examples' K have condition numbers below 30 and each derivative is a chain of a few hundred
    // operations: 2^10 eps is that rounding with a margin.
    CHECK(worst.error <= 1024);
    WARN((engine == Engine::direct ? "direct" : "generated") << ": worst " << worst.error << " eps at " << worst.where);
  }
}

// Stronge through its integration: the steps' series carry the derivatives, and each event's p is
// differentiated implicitly (real_roots.hpp). Central differences at 50 digits, steps 1e-12 of the
// input: truncation of order 1e-24 and rounding of order 1e-50 / 1e-12 = 1e-38, both far below double's
// epsilon, as are the 50-digit integration's bounds (1e-48). 2^12 eps: each step is a series of some
// thirty orders of Cauchy products, a longer chain than the algebraic strategies'. Where sliding stops
// (mu = 0.9) the slow slide is followed in tau (approach_series.hpp), regular to the stop, so the
// derivatives there hold as well and no rounding warning is due.
TEST_CASE("stronge: every derivative of Figure 8 agrees with 50-digit central differences") {
  const char* const options[] = {"stronge:mu=0.4", "stronge:mu=0.4,restitution=newton", "stronge:mu=0.9,restitution=poisson"};
  for (int k = 0; k < 3; ++k) {
    Worst worst;
    against_central_differences<mp::float50>("fig8_side_impact.json", Engine::generated, worst,
                                             {read_strategy_option(options[k], 0)}, "1e-12", 4096);
    INFO(options[k] << ": worst " << worst.error << " eps at " << worst.where << " (" << worst.compared << " compared)");
    CHECK(worst.compared > 40 * 40);
    CHECK(worst.error <= 4096);
    const SensitivityRun run = [&] {
      SensitivityOptions o;
      o.strategies = {read_strategy_option(options[k], 0)};
      return sensitivity(test::read_text(test::example("fig8_side_impact.json")), o);
    }();
    const auto& w = run.results.at(0).warnings;
    CHECK(std::find(w.begin(), w.end(), "rounding") == w.end());
  }
}

}  // namespace check_sensitivity
