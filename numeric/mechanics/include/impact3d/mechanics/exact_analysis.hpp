// A collision in exact rational arithmetic: the quantities that are rational (K, V_ri, the impulses,
// the post-impact states, Delta-V, V_rf, the energies and the ratios) as fractions. A strategy whose
// result needs a square root (the direction of a solution plane, sqrt(P_t^2 + P_z^2) or
// sqrt(V_rt^2 + V_rz^2)) or a transcendental says which; speeds, angles and the PDOF are never rational
// and are left to the 100-digit computation that accompanies this one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "impact3d/mechanics/analysis.hpp"
#include "impact3d/scalar/exact.hpp"

namespace impact3d {

// The same post-impact pipeline as every other scalar type (post_impact.hpp), in exact arithmetic; the
// quantities that need a square root or an angle are left to the 100-digit computation.
using ExactSolution = Solution<rational>;

struct ExactResult {
  std::optional<ExactSolution> solution;
  std::string not_rational;  // why not, when there is no solution
};

// The Problem solved (m', K, V_ri, eps), the maximum-energy-loss impulse, and each strategy's result.
struct ExactAnalysis : Problem<rational> {
  Vec3<rational> P_max_loss;
  std::vector<ExactResult> results;
};

// Throws Irrational when the scene itself is not rational, SolveError and std::invalid_argument as
// analyze() does. Compiled once (numeric/mechanics/src/exact_analysis.cpp): the mechanics in fractions is the
// heaviest instantiation there is, and four of the program's sources ask for it.
ExactAnalysis exact_analyze(const Scene<rational>& s, const std::vector<Strategy<rational>>& strategies,
                            Engine engine = Engine::generated);

}  // namespace impact3d
