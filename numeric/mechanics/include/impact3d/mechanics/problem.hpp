// What one collision fixes for every strategy and engine: m', K, the initial relative velocity.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "impact3d/mechanics/decisions.hpp"
#include "impact3d/mechanics/rounding.hpp"
#include "impact3d/mechanics/scene.hpp"
#include "impact3d/mechanics/strategy.hpp"
#include "impact3d/scalar/types.hpp"

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
  // The 2-norm condition number of K and the amplification of the inputs' rounding into the impulse
  // (rounding.hpp). analyze computes them at once, since it prints them. The lean path (lean.hpp) starts
  // from their cheap upper bounds and computes them, by settle(), only when a decision falls within the
  // bound: until then `unsettled` points at the scene and the two are not yet set.
  mutable Scalar kappa;
  mutable Scalar amplification = Scalar(1);
  Scalar kappa_bound, amplification_bound;  // >= kappa and amplification
  // Not shared between threads while unsettled: settle() writes the mutable members.
  mutable const Scene<Scalar>* unsettled = nullptr;
  Scalar point_speeds = Scalar(0);  // |v_IC1| + |v_IC2|, which the amplification takes (rounding.hpp)
  // The quotient's factor 1 + |V_cp / V_n| that ratios and the decisions on them carry (rounding.hpp).
  Scalar quotient = Scalar(1);

  void settle() const {
    if (!unsettled) return;
    kappa = rounding::spd_condition(K);
    amplification = rounding::amplification(*unsettled, point_speeds, V_ri.x(), kappa);
    unsettled = nullptr;
  }

  // Whether |x| <= limit(kappa or amplification), deciding on the bound when it is far from the limit and
  // on the settled value otherwise. The bounds hold of the exact matrices (rounding.hpp:
  // coefficient_condition_bound, spd_condition_bound); computed, the bounds and the eigenvalues' kappa
  // each carry a relative error of a few eps kappa, and K's smallest eigenvalue, which the trace bound
  // takes as 1, carries K's rounding. The bound is therefore used only while the rounding it implies is
  // trusted (kResultRoundings eps A_bound <= kTrustedFraction, so eps kappa <= 3e-8 and K's rounding is
  // below 10^-6), and doubled, far more than those errors.
  template <typename Limit>
  bool within(const Scalar& x, Limit&& limit, bool of_kappa) const {
    using std::abs;
    if (unsettled && rounding::relative_bound(amplification_bound) <= Scalar(rounding::kTrustedFraction) &&
        abs(x) > Scalar(2) * limit(of_kappa ? kappa_bound : amplification_bound))
      return false;
    settle();
    return abs(x) <= limit(of_kappa ? kappa : amplification);
  }

  // A direction computed from a 3x3 solve is noise once its magnitude is below the solve's forward
  // error (rounding::solve_roundoff).
  bool negligible(const Scalar& x, const Scalar& scale) const {
    if constexpr (std::numeric_limits<Scalar>::is_exact) return x == Scalar(0);
    // A ball's radius is its rounding; one that holds 0 takes the zero branch (the direction undefined),
    // where the other would divide by a ball holding 0.
    else if constexpr (is_enclosure_v<Scalar>) return rounding::within_rounding(x, Scalar(0));
    else return within(x, [&](const Scalar& k) { return rounding::solve_roundoff(k, scale); }, true);
  }
};

// m', K (by the engine E), V_ri and the restitution; the conditioning computed (analyze) or bounded (the
// lean path, which must keep `s` alive while it solves).
template <typename E, typename Scalar>
Problem<Scalar> make_problem(const Scene<Scalar>& s, bool bounded = false) {
  Problem<Scalar> p;
  p.m_prime = reduced_mass(s);
  p.K = E::coefficient_matrix(s);
  const Vec3<Scalar> v_Ic0_W = v_Ic_W(s.body[0]), v_Ic1_W = v_Ic_W(s.body[1]);
  p.V_ri = relative_velocity_C(s, v_Ic0_W, v_Ic1_W);
  p.restitution = s.restitution;
  if constexpr (rounding::tracks_rounding_v<Scalar>) {
    p.quotient = rounding::quotient_factor(p.V_ri);
    p.point_speeds = rounding::point_speeds(v_Ic0_W, v_Ic1_W);
  }
  if (bounded && !is_exact_v<Scalar>) {
    p.kappa_bound = rounding::coefficient_condition_bound(p.K, p.m_prime);
    p.amplification_bound = rounding::amplification_bound(s, p.point_speeds, p.V_ri.x(), p.kappa_bound);
    p.kappa = p.amplification = std::numeric_limits<Scalar>::quiet_NaN();
    p.unsettled = &s;
  } else {
    // K is symmetric positive definite (I plus Gram-type terms), so its eigenvalues give the condition;
    // infinite where rounding made it indefinite. Exact arithmetic has no rounding for it to amplify.
    p.kappa = p.kappa_bound = rounding::spd_condition(p.K);
    p.amplification = p.amplification_bound = rounding::amplification(s, p.point_speeds, p.V_ri.x(), p.kappa);
  }
  return p;
}

// The bodies approach at the impulse centre (V_rn > 0), or there is no impact to solve.
template <typename Scalar>
bool approaching(const Problem<Scalar>& p) {
  const DecisionName<Scalar> name(decision_names::approach);
  return p.V_ri.x() > Scalar(0);
}

template <typename Scalar>
void require_approaching(const Problem<Scalar>& p) {
  if (!approaching(p)) throw SolveError("the bodies are not approaching at the impulse centre (V_rn <= 0)");
}

}  // namespace impact3d
