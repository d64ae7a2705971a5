// One collision solved by any number of strategies: the case-level quantities (m', K, V_ri, impulse
// space) once, then each strategy's impulse and its consequences, by the chosen engine.
#pragma once

#include <Eigen/Eigenvalues>
#include <vector>

#include "impact3d/mechanics/impulse_space.hpp"
#include "impact3d/mechanics/lean.hpp"
#include "impact3d/mechanics/rounding.hpp"
#include "impact3d/scalar/scalars.hpp"

namespace impact3d {

// The Problem it solved (m', K, V_ri, eps, kappa, amplification), and what the analysis adds to it.
template <typename Scalar>
struct Analysis : Problem<Scalar> {
  Engine engine;
  std::array<Mat3<Scalar>, 2> T;      // the paper's T_i = R_CB_i
  ImpulseSpace<Scalar> space;
  std::vector<Solution<Scalar>> solutions;

  const Problem<Scalar>& problem() const { return *this; }
};

template <typename Scalar>
bool case_finite(const Analysis<Scalar>& a) {
  return is_finite(a.m_prime) && all_finite(a.K) && all_finite(a.V_ri) && all_finite(a.space.P_max_loss) &&
         all_finite(a.space.cil_direction) && all_finite(a.space.plane_normal) && all_finite(a.space.plane_offset) &&
         is_finite(a.space.restitution_offset);
}

// A strategy's impulse, with its warnings' text; throws SolveError for a singular constraint system.
template <typename E, typename Scalar>
ImpulseSolution<Scalar> solve_impulse(const Problem<Scalar>& p, const Strategy<Scalar>& st) {
  ImpulseSolution<Scalar> out;
  if (const Singular f = solve_strategy<E>(p, st, out)) throw f.own_words ? SolveError(f.what) : E::singular(f.what);
  return out;
}

template <typename E, typename Scalar>
Analysis<Scalar> analyze_with(const Scene<Scalar>& s, const std::vector<Strategy<Scalar>>& strategies, Engine engine) {
  Analysis<Scalar> a;
  static_cast<Problem<Scalar>&>(a) = make_problem<E>(s);
  const Problem<Scalar>& p = a.problem();
  require_approaching(p);
  a.engine = engine;
  a.T = {R_CB(s, 0), R_CB(s, 1)};
  a.space = impulse_space<E>(p);
  for (std::size_t k = 0; k < strategies.size(); ++k) {
    try {
      a.solutions.push_back(post_impact(s, solve_impulse<E>(p, strategies[k]), p.kappa));
    } catch (SolveError& e) {
      e.strategy = k;
      throw;
    }
    flag_precision(a.solutions.back(), p.amplification, p.kappa);
  }
  if (!case_finite(a)) {
    const std::string text = "a quantity of the case (m', K, its condition or the impulse-space geometry) is not finite "
                             "at this precision";
    for (auto& sol : a.solutions) sol.warnings.push_back({WarningCode::not_finite, text});
  }
  return a;
}

// Throws SolveError when the bodies do not approach or a strategy's constraints admit no impulse, and
// std::invalid_argument when an inertia tensor is not symmetric (scene.hpp).
template <typename Scalar>
Analysis<Scalar> analyze(const Scene<Scalar>& s, const std::vector<Strategy<Scalar>>& strategies,
                         Engine engine = Engine::generated) {
  require_symmetric_inertia(s);
  if (engine == Engine::direct) return analyze_with<direct::DirectEngine>(s, strategies, engine);
  return analyze_with<GeneratedEngine>(s, strategies, engine);
}

// The impulse-space geometry of an analysis's figures, by the engine the analysis used.
template <typename Scalar>
struct Figures {
  ContactPlaneFigure<Scalar> contact;
  std::vector<SolutionPlaneFigure<Scalar>> planes;  // one per solution
};

template <typename E, typename Scalar>
Figures<Scalar> figures_with(const Analysis<Scalar>& a) {
  Figures<Scalar> f{contact_plane_figure<E>(a.problem()), {}};
  for (const auto& s : a.solutions) f.planes.push_back(solution_plane_figure<E>(a.problem(), s.impulse));
  return f;
}

template <typename Scalar>
Figures<Scalar> figures(const Analysis<Scalar>& a) {
  if (a.engine == Engine::direct) return figures_with<direct::DirectEngine>(a);
  return figures_with<GeneratedEngine>(a);
}

}  // namespace impact3d

namespace impact3d {
#define IMPACT3D_EXTERN_ANALYZE_(type, name, u) \
  extern template Analysis<type> analyze(const Scene<type>&, const std::vector<Strategy<type>>&, Engine);
IMPACT3D_SCALARS(IMPACT3D_EXTERN_ANALYZE_)
#undef IMPACT3D_EXTERN_ANALYZE_
}  // namespace impact3d
