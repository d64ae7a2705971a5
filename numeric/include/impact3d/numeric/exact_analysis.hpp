// A collision in exact rational arithmetic: the quantities that are rational (K, V_ri, the impulses,
// the post-impact states, Delta-V, V_rf, the energies and the ratios) as fractions. A strategy whose
// result needs a square root (the direction of a solution plane, sqrt(P_t^2 + P_z^2) or
// sqrt(V_rt^2 + V_rz^2)) or a transcendental says which; speeds, angles and the PDOF are never rational
// and are left to the 100-digit computation that accompanies this one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "impact3d/numeric/analysis.hpp"
#include "impact3d/numeric/exact.hpp"

namespace impact3d {

struct ExactSolution {
  ImpulseSolution<rational> impulse;
  Vec3<rational> P_W;
  std::array<RigidBody<rational>, 2> after;
  std::array<Vec3<rational>, 2> dv_W;
  Vec3<rational> V_rf;
  rational energy_before, energy_after, energy_loss;
};

struct ExactResult {
  std::optional<ExactSolution> solution;
  std::string not_rational;  // why not, when there is no solution
};

struct ExactAnalysis {
  rational m_prime;
  Mat3<rational> K;
  Vec3<rational> V_ri;
  Vec3<rational> P_max_loss;
  std::vector<ExactResult> results;
};

template <typename E>
ExactAnalysis exact_analyze_with(const Scene<rational>& s, const std::vector<Strategy<rational>>& strategies) {
  const Problem<rational> p = make_problem<E>(s);
  require_approaching(p);
  ExactAnalysis a{p.m_prime, p.K, p.V_ri, E::full_impact(p, rational(0)), {}};
  for (std::size_t k = 0; k < strategies.size(); ++k) {
    ExactResult r;
    try {
      ExactSolution x;
      x.impulse = solve_impulse<E>(p, strategies[k]);
      x.P_W = s.R_WC * x.impulse.P_C;
      x.after = {apply_impulse(s.body[0], x.P_W), apply_impulse(s.body[1], Vec3<rational>(-x.P_W))};
      Scene<rational> after = s;
      after.body = x.after;
      for (int i = 0; i < 2; ++i) x.dv_W[i] = x.after[i].v_W - s.body[i].v_W;
      x.V_rf = relative_velocity_C(after);
      x.energy_before = kinetic_energy(s.body[0]) + kinetic_energy(s.body[1]);
      x.energy_after = kinetic_energy(x.after[0]) + kinetic_energy(x.after[1]);
      x.energy_loss = x.energy_before - x.energy_after;
      r.solution = x;
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

// Throws Irrational when the scene itself is not rational, SolveError as analyze() does.
inline ExactAnalysis exact_analyze(const Scene<rational>& s, const std::vector<Strategy<rational>>& strategies,
                                   Engine engine = Engine::generated) {
  if (engine == Engine::direct) return exact_analyze_with<direct::DirectEngine>(s, strategies);
  return exact_analyze_with<GeneratedEngine>(s, strategies);
}

}  // namespace impact3d
