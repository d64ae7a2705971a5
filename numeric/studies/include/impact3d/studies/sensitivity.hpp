// `impact3d sensitivity` as a library (many-cases.md, "sensitivity"): the derivative of every number of
// each result document with respect to every numeric input of the case, by forward-mode automatic
// differentiation through the same templated mechanics (scalar/autodiff.hpp). The branch each result
// takes (regime, cap, signs) is the one its value takes, so the derivative is the regime-fixed one;
// `regime_margin` says how far the deciding quantity is from switching.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/mechanics/problem.hpp"

namespace impact3d::studies {

using case_format::CaseSpec;

struct SensitivityOptions {
  Engine engine = Engine::generated;
  std::vector<StrategySpec> strategies;  // replace the case's, when not empty
};

struct SensitivityResult {
  StrategySpec strategy;
  std::string regime;  // regime_name
  // The deciding quantity and its value: "gir - mu" (pc-crash), "cir - mu" or "gir - mu" (Wach's cap);
  // empty where the strategy decides no regime from the inputs (brach).
  std::string margin_of;
  double regime_margin = 0;
  std::vector<double> margin_derivatives;  // per input
  // Per output of monte_carlo_outputs(): the value as the document writes it (NaN: null), whether the
  // document writes it, and its derivative by each input at [output * inputs + input] (NaN: none, as
  // at a direction of zero length).
  std::vector<double> values;
  std::vector<char> written;
  std::vector<double> derivatives;
  std::vector<std::string> warnings;  // kWarningNames of the result's warnings, in code order
};

struct SensitivityRun {
  Units units = Units::SI;
  Engine engine = Engine::generated;
  std::vector<std::string> inputs;  // paths (case_numbers.hpp, case_inputs)
  std::vector<double> input_values;
  std::vector<std::pair<std::string, std::string>> fixed;  // inputs not differentiated, and why
  std::vector<SensitivityResult> results;

  double derivative(std::size_t result, std::size_t output, std::size_t input) const {
    return results[result].derivatives[output * inputs.size() + input];
  }
};

// Throws CaseError (at the case's path) as `solve` would for the same case: bad input, not approaching,
// a strategy with no solution.
SensitivityRun sensitivity(const std::string& case_text, const SensitivityOptions& o);
// The same for a read case (its strategies replaced by the options', when given).
SensitivityRun sensitivity(CaseSpec spec, const SensitivityOptions& o);

// The relative change of an output per relative change of an input, d * x / y; NaN where x or y is 0.
double elasticity(double derivative, double input, double output);

// The contract's JSON, and a text report (for each result: the regime and its margin, then for ΔV,
// PDOF, post-impact velocities and yaw rates and the energy loss, the inputs ranked by elasticity).
std::string sensitivity_json(const SensitivityRun& run);
std::string sensitivity_text(const SensitivityRun& run, std::size_t top = 8);

}  // namespace impact3d::studies
