// 3D extension of PC-Crash Full Impact / Sliding Impact (eqs 10-20).
//
// Full Impact when mu >= GIR = |P_cp,FI| / P_n,FI (eq 14; equal to eq 20 on the phi_FI plane), otherwise
// Sliding Impact on the plane through n at phi_FI = atan2(P_z,FI, P_t,FI) (eq 15) with P_cp = mu P_n
// (eqs 16-18). The CIR of that plane (eq 19) is reported beside the GIR.
#pragma once

#include <cmath>

#include <array>
#include <optional>
#include <string_view>

#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/strategies/limits.hpp"

namespace impact3d {

// The strategy's entry (strategies/list.hpp): its parameters and how it decides its regime; its solve
// is strategies::solve below.
template <typename Scalar>
struct PcCrash {
  Scalar mu;

  static constexpr std::string_view name = "pc-crash";
  static constexpr std::array<Parameter, 1> parameters{{{"mu", ParameterType::non_negative}}};
  static constexpr std::string_view friction_key = "mu";  // the parameter a sweep over friction varies
  // The values verification checks it over, one row per variant (verify.cpp).
  static constexpr std::array<std::array<ParameterDraw, 1>, 1> verified{{{{{0, 1.2}}}}};
  // Its own first step is the Full Impact: it names that system when singular, no check before it.
  static constexpr bool solves_full_impact = true;
  // The names its regime decision takes (decisions.hpp): at a tie either branch gives the same impulse.
  static constexpr std::array<const char*, 1> regime_decisions{decision_names::pc_crash_regime};

  template <typename Values>
  static PcCrash make(const Values& v) {
    return {*v.number("mu")};
  }
  template <typename To, typename F>
  PcCrash<To> convert(F&& f) const {
    return {f(mu)};
  }
  std::optional<RegimeDecision<Scalar>> regime_decision() const {
    return RegimeDecision<Scalar>{regime_decisions[0], "gir - mu", &ImpulseSolution<Scalar>::gir, mu,
                                  Regime::full, Regime::sliding};
  }
};

}  // namespace impact3d

namespace impact3d::strategies {

// Fills `out`; returns the singular constraint system, if any (then `out` is incomplete).
template <typename Engine, typename Scalar>
Singular solve(const Problem<Scalar>& p, const PcCrash<Scalar>& spec, ImpulseSolution<Scalar>& out) {
  const auto P_fi = Engine::try_full_impact(p, p.restitution);
  if (!P_fi) return {"full impact"};
  const Scalar P_cp = plane_length(P_fi->y(), P_fi->z());
  const PlaneAxes<Scalar> ax = solution_plane(p, P_fi->y(), P_fi->z(), P_cp, magnitude(*P_fi), out,
                                               "phi_FI (eq 15) is undefined: the Full Impact has no contact-plane "
                                               "impulse; the t axis (phi_FI = 0) is used");
  const Scalar gir = P_cp / P_fi->x();
  out.gir = gir;
  out.cir = Engine::try_plane_ratio(p, ax, p.restitution);
  if (!out.cir) return {"pc-crash CIR (eq 19)"};
  flag_if_not_finite(out, *out.cir, "CIR (eq 19)");
  flag_if_undecided(out, p, spec.mu, gir, "GIR (eq 14)");
  bool full;
  {
    const DecisionName<Scalar> name(decision_names::pc_crash_regime);
    full = imposed_or(decision_names::pc_crash_regime, spec.mu >= gir);
  }
  if (full) {
    out.regime = Regime::full;
    out.rows.full = true;
    out.mu = gir;
    out.P_C = *P_fi;
  } else {
    out.regime = Regime::sliding;
    out.mu = spec.mu;
    const auto P = Engine::try_plane_impulse(p, ax, spec.mu);
    if (!P) return {"pc-crash sliding impact (eq 18)"};
    out.P_C = *P;
  }
  return {};
}

}  // namespace impact3d::strategies
