// `impact3d reconstruct` as a library (many-cases.md, "reconstruct"): the unknowns of an evidence file
// (read_evidence.hpp) solved for by weighted least squares on the forward model of the case's one
// strategy. Each regime the strategy can take is fitted on its own, with that regime imposed on the
// mechanics (decisions.hpp, ImposeBranch), from the linear (Gauss-Newton) step of that regime's model;
// a fit is admissible when the fitted inputs decide the regime it imposed. Derivatives are exact, by the
// dual numbers of the sensitivity (autodiff.hpp); the minimizer is Eigen's Levenberg-Marquardt.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/read_evidence.hpp"
#include "impact3d/mechanics/problem.hpp"

namespace impact3d::studies {

using case_format::EvidenceSpec;
using case_format::StrategySpec;
using case_format::Unknown;

struct ReconstructOptions {
  Engine engine = Engine::generated;
  std::optional<StrategySpec> strategy;  // replaces the case's; without it the case must hold exactly one
};

struct EvidenceResidual {
  std::size_t item = 0;   // place in the evidence file
  std::string output;     // "vehicles[0].velocity[1]", or "speed[0]"
  double value = 0, sd = 0;
  double fitted = 0;      // the model's value at the fit (NaN where the result has none)
  double residual = 0;    // fitted - value; an angle's on the circle, in [-180, 180)
  double standardized = 0;  // residual / sd
};

// A combination of the unknowns the evidence does not determine: coefficients per unknown (unit
// length, the largest positive), and the singular value of the standardized Jacobian along it,
// relative to the largest (kUndetermined at most).
struct Undetermined {
  std::vector<double> combination;
  double relative_singular_value = 0;
};

// A singular value of the Jacobian (columns scaled to unit length) at most this, relative to the
// largest, is taken as zero. The Jacobian's rounding leaves undetermined directions near 1e-15. Each
// column being scaled, an unknown that only imprecise evidence sees is still determined; but a
// combination of unknowns that only evidence 1e9 times less precise (in sd) than the evidence on the
// rest determines falls below it too, and is reported undetermined: next to the rest, it is.
inline constexpr double kUndetermined = 1e-9;

struct Fit {
  std::string regime;          // regime_name at the fit
  std::string imposed;         // the regime imposed while fitting ("" when none was)
  bool admissible = true;      // the fitted inputs decide the imposed regime (and the fit converged)
  std::string decided;         // the regime the fitted inputs decide
  bool converged = false;
  std::string solver_status;   // the minimizer's stopping reason
  int evaluations = 0;
  std::vector<double> value;   // per unknown; NaN where undetermined
  std::vector<double> fitted;  // per unknown, the point the fit stopped at (determined or not)
  std::vector<double> sd;      // per unknown; NaN where undetermined
  std::vector<std::vector<double>> correlation;  // NaN where either is undetermined
  std::vector<EvidenceResidual> residuals;
  double chi2 = 0;
  std::size_t dof = 0;
  double p_value = 0;          // NaN without degrees of freedom
  bool identifiable = true;
  std::vector<Undetermined> undetermined;
  std::vector<std::string> warnings;  // the fit's, then the forward result's at the fit
};

struct Reconstruction {
  Units units = Units::SI;
  Engine engine = Engine::generated;
  StrategySpec strategy;
  std::vector<Unknown> unknowns;
  std::vector<double> start;   // per unknown
  Fit best;
  std::vector<Fit> alternatives;  // other admissible fits, by chi2
  // Fits not admitted: the fitted inputs decide another regime than the one imposed, or the fit did not
  // converge.
  std::vector<Fit> inadmissible;
};

// Throws CaseError: for the case as `solve` would; for an unknown or an evidence item the case cannot
// serve, at its path in the evidence file ($.unknowns[1].path, $.evidence[0].output); when the case at
// the starting values has no solution.
Reconstruction reconstruct(const std::string& case_text, const EvidenceSpec& evidence, const ReconstructOptions& o);

// The states at a fit, for a picture: per vehicle, in world axes and the case's units, its CG relative
// to the impulse centre, and its CG velocity before and after the impact.
struct FitStates {
  std::array<std::array<double, 3>, 2> cg{}, before{}, after{};
};
// Throws CaseError where the case has no solution at the fit.
FitStates fit_states(const std::string& case_text, const EvidenceSpec& evidence, const ReconstructOptions& o, const Fit& fit);

// chi2 of the whole model (each point in the regime its inputs decide) with unknowns `a` and `b` at
// each pair of `xs` and `ys` (row-major, ys outer) and the others at the fit; NaN where the case has no
// solution there.
std::vector<double> chi2_grid(const std::string& case_text, const EvidenceSpec& evidence, const ReconstructOptions& o,
                              const Fit& fit, std::size_t a, std::size_t b, const std::vector<double>& xs,
                              const std::vector<double>& ys);

// The contract's JSON, and a text report.
std::string reconstruction_json(const Reconstruction& r);
std::string reconstruction_text(const Reconstruction& r);

}  // namespace impact3d::studies
