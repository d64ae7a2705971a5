// The first-order propagation beside a Monte Carlo run (montecarlo.hpp, Linearized): the case at the
// inputs' means differentiated (sensitivity.hpp), var y = g^T C g with g the derivatives by the
// uncertain inputs and C their covariance.
#include <algorithm>
#include <cmath>
#include <string>
#include <limits>

#include <fmt/format.h>

#include "impact3d/studies/montecarlo_linear.hpp"

#include "impact3d/studies/angle_difference.hpp"
#include "impact3d/studies/sensitivity.hpp"
#include "impact3d/uncertainty/moments.hpp"
#include "not_a_number.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

namespace {

// The quantity an output measures, so that an output that is zero throughout (the normal sliding of a
// planar case) is compared at the scale of its kind rather than at its own rounding noise.
int kind_of(const std::string& path) {
  if (path.ends_with("_deg")) return 0;
  if (path.find("angular_velocity") != std::string::npos) return 1;
  if (path.find("velocity") != std::string::npos || path.find("delta_v") != std::string::npos ||
      path.rfind("sliding.", 0) == 0)
    return 2;
  if (path.rfind("impulse.", 0) == 0) return 3;
  if (path.rfind("energy.", 0) == 0) return 4;
  return 5;  // ratios
}

void compare(StrategySummary& s) {
  Linearized& lin = s.linear;
  double scale[6] = {};
  for (const OutputSummary& o : s.outputs)
    if (o.summary.count) {
      double& at = scale[kind_of(o.output->text)];
      at = std::max(at, std::fabs(o.summary.mean) + o.summary.sd);
    }
  for (const OutputSummary& o : s.outputs) {
    const std::size_t c = static_cast<std::size_t>(o.output - monte_carlo_outputs().data());
    const auto& m = o.summary;
    if (m.count < 2 || !std::isfinite(lin.mean[c]) || !std::isfinite(lin.sd[c])) continue;
    const double dmean = o.output->angle ? angle_difference(m.mean, lin.mean[c]) : m.mean - lin.mean[c];
    const double sd_se = m.sd / std::sqrt(2.0 * static_cast<double>(m.count - 1));
    // Differences below 1e-9 of the kind's scale are rounding, far below any sampling error.
    const double floor = 1e-9 * scale[kind_of(o.output->text)];
    if (std::fabs(dmean) > 0.1 * m.sd + 4 * m.mean_se + floor || std::fabs(lin.sd[c] - m.sd) > 0.1 * m.sd + 4 * sd_se + floor)
      lin.differs.push_back(o.output->text);
  }
}

}  // namespace

void linearize(MonteCarloRun& run, CaseVariants& variants, const UncertaintySpec& u, const MonteCarloOptions& o) {
  const std::size_t m = u.inputs.size(), outputs = monte_carlo_outputs().size();
  std::vector<double> mean(m), sd(m);
  for (std::size_t i = 0; i < m; ++i) {
    const uncertainty::Moments mo = uncertainty::moments(u.inputs[i].distribution);
    mean[i] = mo.mean, sd[i] = mo.sd;
  }
  std::vector<double> rho(m * m, 0.0);
  for (std::size_t i = 0; i < m; ++i) rho[i * m + i] = 1;
  for (const auto& c : u.correlations) rho[c.a * m + c.b] = rho[c.b * m + c.a] = c.rho;

  auto none = [&](const std::string& why) {
    for (auto& s : run.results) s.linear.note = why;
  };
  SensitivityRun sens;
  try {
    SensitivityOptions so;
    so.engine = o.engine;
    so.strategies = o.strategies;
    sens = sensitivity(variants.with(mean.data()), so);
  } catch (const CaseError& e) {
    return none("the case at the inputs' means is refused: " + e.line());
  } catch (const SolveError& e) {
    return none(std::string("the case at the inputs' means has no solution: ") + e.what());
  }
  // Each uncertain input's place among the differentiated ones.
  std::vector<std::size_t> at(m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::string path = path_text(u.inputs[i].path);
    std::size_t j = 0;
    while (j < sens.inputs.size() && sens.inputs[j] != path) ++j;
    if (j == sens.inputs.size()) return none(fmt::format("{} is not differentiated", u.inputs[i].path_text));
    at[i] = j;
  }
  for (std::size_t k = 0; k < run.results.size() && k < sens.results.size(); ++k) {
    const SensitivityResult& r = sens.results[k];
    Linearized& lin = run.results[k].linear;
    lin.regime = r.regime;
    lin.mean.assign(outputs, kNaN);
    lin.sd.assign(outputs, kNaN);
    for (std::size_t c = 0; c < outputs; ++c) {
      if (!r.written[c] || !std::isfinite(r.values[c])) continue;
      double var = 0;
      bool finite = true;
      for (std::size_t i = 0; i < m; ++i) {
        const double gi = r.derivatives[c * sens.inputs.size() + at[i]] * sd[i];
        finite = finite && std::isfinite(gi);
        for (std::size_t j = 0; j < m; ++j)
          var += gi * rho[i * m + j] * r.derivatives[c * sens.inputs.size() + at[j]] * sd[j];
      }
      lin.mean[c] = r.values[c];
      if (finite) lin.sd[c] = std::sqrt(var > 0 ? var : 0);
    }
    const auto& regimes = run.results[k].regimes;
    for (std::size_t g = 0; g < regimes.size(); ++g)
      if (regimes[g] && kRegimeNames[g] != r.regime) lin.regime_switch = true;
    compare(run.results[k]);
  }
}

}  // namespace impact3d::studies
