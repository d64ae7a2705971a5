#include "uncertainty.hpp"

#include <stdexcept>

#include <fmt/format.h>
#include <pybind11/numpy.h>

#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/case_format/read_uncertainty.hpp"
#include "impact3d/studies/sensitivity.hpp"
#include "solve.hpp"

namespace py = pybind11;

namespace impact3d::python {
namespace {

template <typename T>
py::array_t<T> array_of(const T* data, std::size_t n) {
  return py::array_t<T>(static_cast<py::ssize_t>(n), data);
}

// Every sample as arrays: each input by its path; per result its regime (kRegimeNames index, -1 not
// solved), its rejection (0 none, r + 1 the reason r) and each output by its path.
py::dict samples_of(const studies::MonteCarloRun& run) {
  const std::size_t n = run.samples, inputs = run.inputs.size();
  py::dict in;
  for (std::size_t j = 0; j < inputs; ++j) {
    py::array_t<double> a(static_cast<py::ssize_t>(n));
    double* d = a.mutable_data();
    for (std::size_t i = 0; i < n; ++i) d[i] = run.inputs_of[i * inputs + j];
    in[py::str(run.inputs[j])] = a;
  }
  const auto& outputs = case_format::monte_carlo_outputs();
  py::list results;
  for (std::size_t k = 0; k < run.results.size(); ++k) {
    py::dict r;
    r["regime"] = array_of(run.regime_of[k].data(), n);
    r["rejected"] = array_of(run.reason_of[k].data(), n);
    for (std::size_t c = 0; c < outputs.size(); ++c)
      r[py::str(outputs[c].text)] = array_of(run.outputs_of.data() + (k * outputs.size() + c) * n, n);
    results.append(r);
  }
  py::dict out;
  out["inputs"] = in;
  out["results"] = results;
  py::list reasons;
  for (const auto& reason : run.reasons) reasons.append(reason);
  out["reasons"] = reasons;
  return out;
}

}  // namespace

py::tuple montecarlo(const Case& c, const Uncertainty& u, const std::vector<std::string>& strategies,
                     const std::string& precision, const std::string& engine, unsigned jobs,
                     std::optional<std::uint64_t> samples, std::optional<std::uint64_t> seed, bool keep) {
  // The CLI's bounds on --samples and --jobs, in its words.
  if (samples && (*samples < 1 || *samples > case_format::kMaxSamples))
    throw std::invalid_argument(fmt::format("samples: from 1 to {}, not {}", case_format::kMaxSamples, *samples));
  if (jobs > kMaxJobs) throw std::invalid_argument(fmt::format("jobs: at most {}, not {}", kMaxJobs, jobs));
  studies::MonteCarloOptions o;
  if (const std::string problem = studies::precision_problem(precision); !problem.empty())
    throw std::invalid_argument("precision: " + problem);  // as solve says it
  o.precision = studies::parse_precision(precision);
  o.engine = engine_named(engine);
  o.jobs = jobs;
  o.keep_samples = keep;
  if (!strategies.empty())
    guarded("", [&] {  // an option's problem, as the CLI names it: --strategy[i]
      case_format::CaseSpec spec = c.spec;
      replace_strategies(spec, strategies);
      o.strategies = spec.strategies;
    });
  case_format::UncertaintySpec spec = guarded(u.source, [&] { return case_format::read_uncertainty(u.text); });
  if (samples) spec.samples = *samples;
  if (seed) spec.seed = *seed;
  studies::MonteCarloRun run;
  {
    py::gil_scoped_release released;
    run = guarded(u.source, [&] {
      try {
        return studies::montecarlo(c.text, spec, o);
      } catch (const case_format::CaseError& e) {
        if (samples && e.path == "$.samples") throw case_format::CaseError("--samples", e.what());
        throw;
      }
    });
  }
  return py::make_tuple(studies::montecarlo_json(run), keep ? py::object(samples_of(run)) : py::object(py::none()));
}

std::string sensitivity_json(const Case& c, const std::vector<std::string>& strategies, const std::string& engine) {
  studies::SensitivityOptions o;
  o.engine = engine_named(engine);
  return guarded(c.source, [&] {
    case_format::CaseSpec spec = c.spec;
    replace_strategies(spec, strategies);
    if (!strategies.empty()) o.strategies = spec.strategies;
    return studies::sensitivity_json(studies::sensitivity(spec, o));
  });
}

}  // namespace impact3d::python
