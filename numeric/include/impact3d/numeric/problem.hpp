// What one collision fixes for every strategy and engine: m', K, the initial relative velocity.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "impact3d/numeric/rounding.hpp"
#include "impact3d/numeric/strategy.hpp"
#include "impact3d/numeric/types.hpp"

namespace impact3d {

// The two ways impact3d computes K and the impulses: the closed forms generated from the GiNaC
// derivation (production), and 3x3 linear solves of the constraints (the independent reference).
enum class Engine { generated, direct };

inline const char* engine_name(Engine e) { return e == Engine::generated ? "generated" : "direct"; }

template <typename Scalar>
struct Problem {
  Scalar m_prime;
  Mat3<Scalar> K;
  Vec3<Scalar> V_ri;  // contact axes
  Scalar restitution;
  Scalar kappa;       // 2-norm condition number of K
  Scalar amplification = Scalar(1);  // of the inputs' rounding into the impulse (rounding.hpp)

  // A direction computed from a 3x3 solve is noise once its magnitude is below the solve's forward
  // error (rounding::solve_roundoff).
  bool negligible(const Scalar& x, const Scalar& scale) const {
    using std::abs;
    if constexpr (std::numeric_limits<Scalar>::is_exact) return x == Scalar(0);
    else return abs(x) <= rounding::solve_roundoff(kappa, scale);
  }
};

// The bodies approach at the impulse centre (V_rn > 0), or there is no impact to solve.
template <typename Scalar>
void require_approaching(const Problem<Scalar>& p) {
  if (!(p.V_ri.x() > Scalar(0))) throw SolveError("the bodies are not approaching at the impulse centre (V_rn <= 0)");
}

}  // namespace impact3d
