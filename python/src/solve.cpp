#include "solve.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "impact3d/io/escape.hpp"
#include "impact3d/io/limits.hpp"
#include "impact3d/io/render.hpp"
#include "impact3d/io/strategy_option.hpp"
#include "impact3d/numeric/units.hpp"

namespace impact3d::python {

Engine engine_named(const std::string& name) {
  if (name == "generated") return Engine::generated;
  if (name == "direct") return Engine::direct;
  throw std::invalid_argument(fmt::format("engine: generated or direct, not {}", io::printable(name)));
}

void replace_strategies(io::CaseSpec& spec, const std::vector<std::string>& strategies) {
  if (strategies.empty()) return;
  if (strategies.size() > io::limits::kStrategies)
    throw io::CaseError("--strategy", fmt::format("more than {} strategies", io::limits::kStrategies));
  spec.strategies.clear();
  for (std::size_t i = 0; i < strategies.size(); ++i)
    spec.strategies.push_back(io::read_strategy_option(strategies[i], static_cast<int>(i)));
}

std::string solve_json(const Case& c, const std::vector<std::string>& strategies, const std::string& engine,
                       const std::string& precision, const std::optional<std::string>& units) {
  io::RenderOptions o;
  o.format = "json";
  o.engine = engine_named(engine);
  if (const std::string problem = io::precision_problem(precision); !problem.empty())
    throw std::invalid_argument("precision: " + problem);
  if (units) {
    o.units = units_named(*units);
    if (!o.units) throw std::invalid_argument(fmt::format("units: SI, US or metric-kmh, not {}", io::printable(*units)));
  }
  return guarded(c.source, [&] {
    io::CaseSpec spec = c.spec;
    replace_strategies(spec, strategies);
    try {
      return io::render(spec, precision, o);
    } catch (const SolveError& e) {
      throw io::no_solution(spec, e);  // named by the strategy's path, as the CLI names it
    }
  });
}

}  // namespace impact3d::python
