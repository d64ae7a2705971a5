// Wach: the solution plane contains n and the initial sliding velocity (eq 21), P_t' = mu P_n (eq 22),
// P_z' = 0, and mu capped at the plane's CIR (eq 19, Wach) or GIR (eq 20, Virtual CRASH guide).
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/strategies/limits.hpp"

namespace impact3d {

enum class WachLimit { cir, gir };  // in the order of the parameter's choices

inline constexpr std::string_view wach_limit_names[] = {"cir", "gir"};

// The strategy's entry (strategies/list.hpp): its parameters and how it decides its regime; its solve
// is strategies::solve below.
// Tangent aligned with the initial sliding velocity (eqs 21-22), ratio capped at the plane's CIR or GIR.
template <typename Scalar>
struct Wach {
  Scalar mu;
  WachLimit limit = WachLimit::cir;

  static constexpr std::string_view name = "wach";
  static constexpr std::array<Parameter, 2> parameters{
      {{"mu", ParameterType::non_negative}, {"limit", ParameterType::choice, wach_limit_names}}};
  static constexpr std::string_view friction_key = "mu";
  static constexpr std::array<std::array<ParameterDraw, 2>, 2> verified{
      {{{{0, 1.2}, {.choice = "cir"}}}, {{{0, 1.2}, {.choice = "gir"}}}}};
  static constexpr bool solves_full_impact = false;
  static constexpr std::array<const char*, 2> regime_decisions{decision_names::wach_cap_cir, decision_names::wach_cap_gir};

  template <typename Values>
  static Wach make(const Values& v) {
    return {*v.number("mu"), static_cast<WachLimit>(v.choice_index("limit"))};
  }
  template <typename To, typename F>
  Wach<To> convert(F&& f) const {
    return {f(mu), limit};
  }
  std::optional<RegimeDecision<Scalar>> regime_decision() const {
    const bool cir = limit == WachLimit::cir;
    return RegimeDecision<Scalar>{regime_decisions[cir ? 0 : 1],
                                  cir ? "cir - mu" : "gir - mu",
                                  cir ? &ImpulseSolution<Scalar>::cir : &ImpulseSolution<Scalar>::gir, mu,
                                  Regime::capped, Regime::sliding};
  }
};

}  // namespace impact3d

namespace impact3d::strategies {

// Fills `out`; returns the singular constraint system, if any (then `out` is incomplete).
template <typename Engine, typename Scalar>
Singular solve(const Problem<Scalar>& p, const Wach<Scalar>& spec, ImpulseSolution<Scalar>& out) {
  PlaneAxes<Scalar> ax = solution_plane(p, p.V_ri.y(), p.V_ri.z(), plane_length(p.V_ri.y(), p.V_ri.z()),
                                         magnitude(p.V_ri), out,
                                         "phi (eq 21) is undefined: there is no initial sliding velocity; "
                                         "the t axis is used, directed so that the cap is not negative");
  out.cir = Engine::try_plane_ratio(p, ax, p.restitution);
  if (!out.cir) return {"wach CIR (eq 19)"};
  out.gir = Engine::try_plane_ratio(p, ax, Scalar(0));
  if (!out.gir) return {"wach GIR (eq 20)"};
  const bool on_cir = spec.limit == WachLimit::cir;
  const auto& cap = on_cir ? out.cir : out.gir;  // the cap used; a flip below negates it in place
  if (has_warning(out.codes, WarningCode::plane_undefined)) {
    // Without sliding the axis's direction is a convention, and the caps (eqs 19-20) are odd in it: on
    // +t a negative cap would cap every mu >= 0, so that mu = 0 still gave the sticking impulse. Directed
    // so that the cap is not negative, the impulse is friction toward sticking, capped where it sticks,
    // whichever way the contact frame's t axis points.
    bool flip;
    {
      const DecisionName<Scalar> name(decision_names::fallback_direction);
      flip = *cap < Scalar(0);
    }
    if (flip) {
      ax = {Scalar(-1), Scalar(0)};
      out.cir = Scalar(-*out.cir);
      out.gir = Scalar(-*out.gir);
      out.plane = ax;
      if constexpr (!is_exact_v<Scalar>)
        if (out.for_report) out.plane_angle_deg = Scalar(180);
    }
  }
  flag_if_not_finite(out, *out.cir, "CIR (eq 19)");
  flag_if_not_finite(out, *out.gir, "GIR (eq 20)");
  const Scalar limit = *cap;
  flag_if_undecided(out, p, spec.mu, limit, on_cir ? "CIR (eq 19)" : "GIR (eq 20)");
  bool capped;
  {
    const char* decision = on_cir ? decision_names::wach_cap_cir : decision_names::wach_cap_gir;
    const DecisionName<Scalar> name(decision);
    capped = imposed_or(decision, spec.mu >= limit);
  }
  out.regime = capped ? Regime::capped : Regime::sliding;
  if (capped && on_cir) {  // the CIR's rows: no sliding along the plane's axis (eq 19)
    out.rows.zero_rows = "Wach capped at its CIR, no sliding along its plane's axis (eqs 19, 21)";
    if (has_warning(out.codes, WarningCode::plane_undefined)) out.rows.t_zero = true;  // the axis is +-t
    else out.rows.along_plane_zero = true;
  }
  out.mu = capped ? limit : spec.mu;
  flag_if_negative_ratio(out, *out.mu, "impulse ratio");
  const auto P = Engine::try_plane_impulse(p, ax, *out.mu);
  if (!P) return {"wach (eqs 18, 22)"};
  out.P_C = *P;
  return {};
}

}  // namespace impact3d::strategies
