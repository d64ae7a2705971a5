// One collision solved by any number of strategies: the case-level quantities (m', K, V_ri, impulse
// space) once, then each strategy's impulse and its consequences.
#pragma once

#include <Eigen/Eigenvalues>
#include <vector>

#include "impact3d/numeric/direct/brach.hpp"
#include "impact3d/numeric/direct/coefficient_matrix.hpp"
#include "impact3d/numeric/direct/impulse_space.hpp"
#include "impact3d/numeric/direct/pc_crash.hpp"
#include "impact3d/numeric/direct/wach.hpp"
#include "impact3d/numeric/post_impact.hpp"

namespace impact3d {

template <typename Scalar>
struct Analysis {
  Scalar m_prime;
  Mat3<Scalar> K;
  Scalar kappa;                       // 2-norm condition number of K
  std::array<Mat3<Scalar>, 2> T;      // the paper's T_i = R_CB_i
  Vec3<Scalar> V_ri;                  // contact axes
  ImpulseSpace<Scalar> space;
  std::vector<Solution<Scalar>> solutions;
};

template <typename Scalar>
direct::Problem<Scalar> direct_problem(const Scene<Scalar>& s) {
  direct::Problem<Scalar> p;
  p.m_prime = reduced_mass(s);
  p.K = direct::coefficient_matrix(s);
  p.V_ri = relative_velocity_C(s);
  p.restitution = s.restitution;
  // K is symmetric positive definite (I plus Gram-type terms), so its eigenvalues give the condition.
  Eigen::SelfAdjointEigenSolver<Mat3<Scalar>> eig(p.K, Eigen::EigenvaluesOnly);
  p.kappa = eig.eigenvalues().maxCoeff() / eig.eigenvalues().minCoeff();
  return p;
}

template <typename Scalar>
ImpulseSolution<Scalar> solve_impulse(const direct::Problem<Scalar>& p, const Strategy<Scalar>& st) {
  if (auto* pc = std::get_if<PcCrash<Scalar>>(&st)) return direct::solve_pc_crash(p, *pc);
  if (auto* w = std::get_if<Wach<Scalar>>(&st)) return direct::solve_wach(p, *w);
  return direct::solve_brach(p, std::get<Brach<Scalar>>(st));
}

// Throws SolveError when the bodies do not approach or a strategy's constraints are singular.
template <typename Scalar>
Analysis<Scalar> analyze(const Scene<Scalar>& s, const std::vector<Strategy<Scalar>>& strategies) {
  const direct::Problem<Scalar> p = direct_problem(s);
  if (!(p.V_ri.x() > Scalar(0)))
    throw SolveError("the bodies are not approaching at the impulse centre (V_rn <= 0)");
  Analysis<Scalar> a;
  a.m_prime = p.m_prime;
  a.K = p.K;
  a.kappa = p.kappa;
  a.T = {R_CB(s, 0), R_CB(s, 1)};
  a.V_ri = p.V_ri;
  a.space = direct::impulse_space(p);
  for (const auto& st : strategies) a.solutions.push_back(post_impact(s, solve_impulse(p, st), p.kappa));
  return a;
}

}  // namespace impact3d

namespace impact3d {
extern template Analysis<double> analyze(const Scene<double>&, const std::vector<Strategy<double>>&);
extern template Analysis<long double> analyze(const Scene<long double>&, const std::vector<Strategy<long double>>&);
}  // namespace impact3d
