// One collision solved by any number of strategies: the case-level quantities (m', K, V_ri, impulse
// space) once, then each strategy's impulse and its consequences, by the chosen engine.
#pragma once

#include <Eigen/Eigenvalues>
#include <vector>

#include "impact3d/numeric/direct/engine.hpp"
#include "impact3d/numeric/generated_engine.hpp"
#include "impact3d/numeric/impulse_space.hpp"
#include "impact3d/numeric/post_impact.hpp"
#include "impact3d/numeric/strategies/brach.hpp"
#include "impact3d/numeric/strategies/pc_crash.hpp"
#include "impact3d/numeric/strategies/wach.hpp"

namespace impact3d {

template <typename Scalar>
struct Analysis {
  Engine engine;
  Scalar m_prime;
  Mat3<Scalar> K;
  Scalar kappa;                       // 2-norm condition number of K
  std::array<Mat3<Scalar>, 2> T;      // the paper's T_i = R_CB_i
  Vec3<Scalar> V_ri;                  // contact axes
  ImpulseSpace<Scalar> space;
  std::vector<Solution<Scalar>> solutions;
};

template <typename E, typename Scalar>
Problem<Scalar> make_problem(const Scene<Scalar>& s) {
  Problem<Scalar> p;
  p.m_prime = reduced_mass(s);
  p.K = E::coefficient_matrix(s);
  p.V_ri = relative_velocity_C(s);
  p.restitution = s.restitution;
  // K is symmetric positive definite (I plus Gram-type terms), so its eigenvalues give the condition.
  // Exact arithmetic has no rounding for it to amplify.
  if constexpr (is_exact_v<Scalar>) {
    p.kappa = 1;
  } else {
    Eigen::SelfAdjointEigenSolver<Mat3<Scalar>> eig(p.K, Eigen::EigenvaluesOnly);
    p.kappa = eig.eigenvalues().maxCoeff() / eig.eigenvalues().minCoeff();
  }
  return p;
}

template <typename E, typename Scalar>
ImpulseSolution<Scalar> solve_impulse(const Problem<Scalar>& p, const Strategy<Scalar>& st) {
  if (auto* pc = std::get_if<PcCrash<Scalar>>(&st)) return strategies::pc_crash<E>(p, *pc);
  if (auto* w = std::get_if<Wach<Scalar>>(&st)) return strategies::wach<E>(p, *w);
  return strategies::brach<E>(p, std::get<Brach<Scalar>>(st));
}

template <typename E, typename Scalar>
Analysis<Scalar> analyze_with(const Scene<Scalar>& s, const std::vector<Strategy<Scalar>>& strategies, Engine engine) {
  const Problem<Scalar> p = make_problem<E>(s);
  if (!(p.V_ri.x() > Scalar(0)))
    throw SolveError("the bodies are not approaching at the impulse centre (V_rn <= 0)");
  Analysis<Scalar> a;
  a.engine = engine;
  a.m_prime = p.m_prime;
  a.K = p.K;
  a.kappa = p.kappa;
  a.T = {R_CB(s, 0), R_CB(s, 1)};
  a.V_ri = p.V_ri;
  a.space = impulse_space<E>(p);
  for (const auto& st : strategies) a.solutions.push_back(post_impact(s, solve_impulse<E>(p, st), p.kappa));
  return a;
}

// The problem an analysis solved (m', K, V_ri, kappa), with the scene's restitution: what further
// solves of the same collision (figures, sweeps of the constraints) start from.
template <typename Scalar>
Problem<Scalar> problem_of(const Analysis<Scalar>& a, const Scalar& restitution) {
  return {a.m_prime, a.K, a.V_ri, restitution, a.kappa};
}

// Throws SolveError when the bodies do not approach or a strategy's constraints admit no impulse.
template <typename Scalar>
Analysis<Scalar> analyze(const Scene<Scalar>& s, const std::vector<Strategy<Scalar>>& strategies,
                         Engine engine = Engine::generated) {
  if (engine == Engine::direct) return analyze_with<direct::DirectEngine>(s, strategies, engine);
  return analyze_with<GeneratedEngine>(s, strategies, engine);
}

}  // namespace impact3d

namespace impact3d {
extern template Analysis<double> analyze(const Scene<double>&, const std::vector<Strategy<double>>&, Engine);
extern template Analysis<long double> analyze(const Scene<long double>&, const std::vector<Strategy<long double>>&, Engine);
}  // namespace impact3d
