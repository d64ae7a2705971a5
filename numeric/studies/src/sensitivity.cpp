// Sensitivities by forward-mode automatic differentiation (sensitivity.hpp). The case is first solved
// at double exactly as `solve` solves it, so that every refusal is solve's; then once more on dual
// numbers seeded at the case's inputs (to_scene.hpp, DualSeeds).
#include "impact3d/studies/sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "impact3d/case_format/case_numbers.hpp"
#include "impact3d/studies/result_numbers.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/mechanics/dual_analysis.hpp"
#include "not_a_number.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

namespace {

// The deciding quantity of a strategy's regime, limit - mu, with its name; none where the strategy
// decides no regime from the inputs.
std::optional<std::pair<std::string, Dual>> margin(const Strategy<Dual>& st, const ImpulseSolution<Dual>& imp) {
  const auto d = regime_decision(st);
  if (!d || !(imp.*d->limit)) return std::nullopt;
  return std::pair<std::string, Dual>{d->margin, Dual(*(imp.*d->limit) - d->mu)};
}

}  // namespace

double elasticity(double derivative, double input, double output) {
  if (input == 0 || output == 0 || !std::isfinite(output)) return kNaN;
  return derivative * input / output;
}

SensitivityRun sensitivity(const std::string& case_text, const SensitivityOptions& o) {
  return sensitivity(read_case(case_text), o);
}

SensitivityRun sensitivity(CaseSpec spec, const SensitivityOptions& o) {
  if (!o.strategies.empty()) spec.strategies = o.strategies;
  try {
    (void)analyze(to_scene<double>(spec), to_strategies<double>(spec), o.engine);
  } catch (const SolveError& e) {
    throw no_solution(spec, e);
  }

  SensitivityRun run;
  run.units = spec.units;
  run.engine = o.engine;
  CaseInputs in = case_inputs(spec);
  run.fixed = in.fixed;
  DualSeeds seeds;
  for (std::size_t j = 0; j < in.inputs.size(); ++j) {
    run.inputs.push_back(in.inputs[j].path);
    run.input_values.push_back(scalar_from_text<double>(in.inputs[j].numbers.front()->text));
    for (const Number* n : in.inputs[j].numbers) seeds.index.emplace_back(n, static_cast<int>(j));
  }
  const std::size_t outputs = monte_carlo_outputs().size(), inputs = run.inputs.size();
  for (const StrategySpec& st : spec.strategies) {
    SensitivityResult r;
    r.strategy = st;
    r.derivatives.assign(outputs * inputs, kNaN);
    run.results.push_back(std::move(r));
  }
  // kDualWidth inputs a pass; the values, regimes and warnings are each pass's alike (the derivatives
  // never steer a branch), and are taken from the first.
  std::vector<Dual> v(outputs);
  for (std::size_t first = 0; first == 0 || first < inputs; first += kDualWidth) {
    seeds.first = static_cast<int>(first);
    const std::size_t width = std::min<std::size_t>(kDualWidth, inputs - first);
    Scene<Dual> scene;
    std::vector<Strategy<Dual>> strategies;
    {
      const DualSeedScope scope(seeds);
      scene = to_scene<Dual>(spec);
      strategies = to_strategies<Dual>(spec);
    }
    const Analysis<Dual> a = analyze(scene, strategies, o.engine);
    const UnitFactors<Dual> f = unit_factors<Dual>(spec.units);
    for (std::size_t k = 0; k < a.solutions.size(); ++k) {
      const Solution<Dual>& sol = a.solutions[k];
      SensitivityResult& r = run.results[k];
      std::vector<char> written(outputs, 0);
      numbers_of_solution(sol, f, v.data(), written.data());
      const auto m = margin(strategies[k], sol.impulse);
      if (first == 0) {
        r.regime = regime_name(sol.impulse.regime);
        r.written = written;
        r.values.resize(outputs);
        for (std::size_t c = 0; c < outputs; ++c) r.values[c] = written[c] ? v[c].value() : kNaN;
        if (m) {
          r.margin_of = m->first;
          r.regime_margin = m->second.value();
          r.margin_derivatives.assign(inputs, kNaN);
        }
        WarningSet codes = 0;
        for (const auto& w : sol.warnings) codes |= warning_bit(w.code);
        for (std::size_t w = 0; w < kWarningNames.size(); ++w)
          if (has_warning(codes, static_cast<WarningCode>(w))) r.warnings.emplace_back(kWarningNames[w]);
      }
      for (std::size_t c = 0; c < outputs; ++c) {
        if (!r.written[c] || !std::isfinite(r.values[c])) continue;
        for (std::size_t j = 0; j < width; ++j) r.derivatives[c * inputs + first + j] = v[c].derivatives()[static_cast<Eigen::Index>(j)];
      }
      if (m && !r.margin_derivatives.empty())
        for (std::size_t j = 0; j < width; ++j) r.margin_derivatives[first + j] = m->second.derivatives()[static_cast<Eigen::Index>(j)];
    }
  }
  return run;
}

}  // namespace impact3d::studies
