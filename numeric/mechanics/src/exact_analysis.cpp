// exact_analysis.hpp: the strategies solved in fractions, by either engine.
#include "impact3d/mechanics/exact_analysis.hpp"

namespace impact3d {

namespace {

template <typename E>
ExactAnalysis exact_analyze_with(const Scene<rational>& s, const std::vector<Strategy<rational>>& strategies) {
  const Problem<rational> p = make_problem<E>(s);
  require_approaching(p);
  ExactAnalysis a{p, E::full_impact(p, rational(0)), {}};
  for (std::size_t k = 0; k < strategies.size(); ++k) {
    ExactResult r;
    try {
      r.solution = post_impact(s, solve_impulse<E>(p, strategies[k]), p.kappa);
    } catch (const Irrational& e) {
      r.not_rational = e.what();
    } catch (const std::overflow_error&) {
      SolveError e("a strategy's constraints admit no unique impulse (division by zero)");
      e.strategy = k;
      throw e;
    } catch (SolveError& e) {
      e.strategy = k;
      throw;
    }
    a.results.push_back(std::move(r));
  }
  return a;
}

}  // namespace

ExactAnalysis exact_analyze(const Scene<rational>& s, const std::vector<Strategy<rational>>& strategies, Engine engine) {
  require_symmetric_inertia(s);
  if (engine == Engine::direct) return exact_analyze_with<direct::DirectEngine>(s, strategies);
  return exact_analyze_with<GeneratedEngine>(s, strategies);
}

}  // namespace impact3d
