// Brach: independent impulse ratios P_t = mu_t P_n, P_z = mu_z P_n (eqs 23-24); a ratio given as
// "critical" is replaced by the condition that sliding along its axis stops (eqs 25-26, both: eq 27).
// The critical ratio of each axis, given the other ratio as used, is reported as a limit.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/strategies/limits.hpp"

namespace impact3d {

// The strategy's entry (strategies/list.hpp): its parameters; its solve is strategies::solve below.
// Independent impulse ratios (eqs 23-27); an empty ratio means "critical". It decides no regime from the
// inputs.
template <typename Scalar>
struct Brach {
  std::optional<Scalar> mu_t, mu_z;

  static constexpr std::string_view name = "brach";
  static constexpr std::array<Parameter, 2> parameters{
      {{"mu_t", ParameterType::ratio_or_critical}, {"mu_z", ParameterType::ratio_or_critical}}};
  static constexpr std::string_view friction_key = "mu_t";
  static constexpr std::array<std::array<ParameterDraw, 2>, 2> verified{
      {{{{-0.5, 0.5}, {-0.3, 0.3}}}, {{{.critical = true}, {.critical = true}}}}};
  static constexpr bool solves_full_impact = false;
  static constexpr std::array<const char*, 0> regime_decisions{};

  template <typename Values>
  static Brach make(const Values& v) {
    return {v.number("mu_t"), v.number("mu_z")};
  }
  template <typename To, typename F>
  Brach<To> convert(F&& f) const {
    auto opt = [&](const std::optional<Scalar>& x) { return x ? std::optional<To>(f(*x)) : std::nullopt; };
    return {opt(mu_t), opt(mu_z)};
  }
  std::optional<RegimeDecision<Scalar>> regime_decision() const { return std::nullopt; }
};

}  // namespace impact3d

namespace impact3d::strategies {

// Fills `out`; returns the singular constraint system, if any (then `out` is incomplete).
template <typename Engine, typename Scalar>
Singular solve(const Problem<Scalar>& p, const Brach<Scalar>& spec, ImpulseSolution<Scalar>& out) {
  out.regime = Regime::as_given;
  out.rows.t_zero = !spec.mu_t;  // critical: the no-sliding row along t (eqs 25, 27)
  out.rows.z_zero = !spec.mu_z;
  out.rows.zero_rows = "Brach's critical ratio, the no-sliding row (eqs 25-27)";
  const auto P = Engine::try_brach_impulse(p, spec.mu_t, spec.mu_z);
  if (!P) return {"brach (eqs 24-27)"};
  out.P_C = *P;
  out.mu_t = out.P_C.y() / out.P_C.x();
  out.mu_z = out.P_C.z() / out.P_C.x();
  const auto P_tc = Engine::try_brach_impulse(p, std::optional<Scalar>(), out.mu_z);
  if (!P_tc) return {"brach critical mu_t (eq 25)"};
  const auto P_zc = Engine::try_brach_impulse(p, out.mu_t, std::optional<Scalar>());
  if (!P_zc) return {"brach critical mu_z (eq 26)"};
  out.mu_t_critical = P_tc->y() / P_tc->x();
  out.mu_z_critical = P_zc->z() / P_zc->x();
  flag_if_not_finite(out, *out.mu_t, "mu_t");
  flag_if_not_finite(out, *out.mu_z, "mu_z");
  flag_if_not_finite(out, *out.mu_t_critical, "mu_t critical (eq 25)");
  flag_if_not_finite(out, *out.mu_z_critical, "mu_z critical (eq 26)");
  return {};
}

}  // namespace impact3d::strategies
