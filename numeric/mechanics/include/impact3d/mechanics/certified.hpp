// A collision solved in ball arithmetic (issue 14): every strategy through the same analyze as every
// other scalar, each with the decisions it took (decisions.hpp) and, for each it could not decide at
// the working precision, the result of the other branch. Exact ties are recognized by the rational
// solve, where the case is rational.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "impact3d/mechanics/analysis.hpp"
#include "impact3d/scalar/ball.hpp"
#include "impact3d/scalar/exact.hpp"

namespace impact3d {

// The branch a decision did not take: its solution, or why there is none.
struct CertifiedAlternative {
  std::string decision;
  std::optional<Solution<Ball>> solution;
  std::vector<Decision> decisions;
  std::string failure;
};

struct CertifiedAnalysis {
  Analysis<Ball> analysis;  // the case-level quantities, and each strategy's solution on its midpoint branches
  std::vector<std::vector<Decision>> decisions;               // per strategy
  std::vector<std::vector<CertifiedAlternative>> alternatives;  // per strategy: one per undecided decision
  long bits = 0;

  bool undecided() const {
    for (const auto& list : decisions)
      for (const auto& d : list)
        if (d.status == DecisionStatus::undecided) return true;
    return false;
  }
};

// At the thread's ball_bits. Throws SolveError as analyze does; where the bodies' approach itself is
// undecided, the message says so.
CertifiedAnalysis certified_analyze(const Scene<Ball>& s, const std::vector<Strategy<Ball>>& strategies,
                                    Engine engine = Engine::generated);

// The names of `decisions` (of one strategy's certified solve, `balls` its solution) that are exact ties
// by the exact solution of the same strategy: mu equal to the limit it is compared with; P_n, V_rn after,
// the energy loss, the ratio used, the solution plane's direction or (on Wach's fallback axis) the cap
// exactly zero; for a name that asks several such questions, each whose ball holds 0. Only
// undecided decisions are looked at, and none after an undecided one that chooses the impulse and is no
// tie: there the balls may have taken a branch the exact solve does not. The list's order is that of each
// name's first comparison (DecisionLog::record), which is the order taken while each name that chooses
// the impulse (the plane, the fallback axis, the cap or regime) is compared once, after the approach and
// before the post-impact states, as the strategies do.
// `same_result_at_tie` says whether both branches of a tie give the same result (a regime or cap: the
// impulse is continuous there); a category (the volume, the sliding's change, a warning) is not.
bool same_result_at_tie(const std::string& decision);

// Whether a decision chooses the impulse (and with it every state after): the regime, the cap, the
// solution plane, or a comparison the mechanics do not name. The others describe a result (its volume,
// sliding, swerve, PDOF, warnings), and an enclosure that leaves only those undecided still holds the
// impulse and the states.
bool chooses_impulse(const std::string& decision);
std::vector<std::string> exact_ties(const std::vector<Decision>& decisions, const Strategy<rational>& strategy,
                                    const Solution<rational>& exact, const Solution<Ball>& balls);

}  // namespace impact3d
