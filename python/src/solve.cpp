#include "solve.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/limits.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/strategy_option.hpp"
#include "impact3d/mechanics/units.hpp"

namespace impact3d::python {

Engine engine_named(const std::string& name) {
  if (name == "generated") return Engine::generated;
  if (name == "direct") return Engine::direct;
  throw std::invalid_argument(fmt::format("engine: generated or direct, not {}", case_format::printable(name)));
}

void replace_strategies(case_format::CaseSpec& spec, const std::vector<std::string>& strategies) {
  if (strategies.empty()) return;
  if (strategies.size() > case_format::limits::kStrategies)
    throw case_format::CaseError("--strategy", fmt::format("more than {} strategies", case_format::limits::kStrategies));
  spec.strategies.clear();
  for (std::size_t i = 0; i < strategies.size(); ++i)
    spec.strategies.push_back(case_format::read_strategy_option(strategies[i], static_cast<int>(i)));
}

std::string solve_json(const Case& c, const std::vector<std::string>& strategies, const std::string& engine,
                       const std::string& precision, const std::optional<std::string>& units) {
  case_format::RenderOptions o;
  o.format = case_format::Format::json;
  o.engine = engine_named(engine);
  if (const std::string problem = studies::precision_problem(precision); !problem.empty())
    throw std::invalid_argument("precision: " + problem);
  const studies::PrecisionChoice p = studies::parse_precision(precision);  // the name is one it takes
  if (units) {
    o.units = units_named(*units);
    if (!o.units) throw std::invalid_argument(fmt::format("units: SI, US or metric-kmh, not {}", case_format::printable(*units)));
  }
  return guarded(c.source, [&] {
    case_format::CaseSpec spec = c.spec;
    replace_strategies(spec, strategies);
    try {
      return studies::render(spec, p, o);
    } catch (const SolveError& e) {
      throw case_format::no_solution(spec, e);  // named by the strategy's path, as the CLI names it
    }
  });
}

}  // namespace impact3d::python
