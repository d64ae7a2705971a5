// Stronge: the impact followed through the normal impulse with Coulomb friction mu (stronge/integrate.hpp),
// ended by the restitution law the case names, the case's restitution its coefficient. Not a point chosen
// by constraints on the final state: the impulse is the integral, so no constraint row holds exactly.
// The regime is `full` when the contact sticks at the end, `sliding` when it slides.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/rounding.hpp"
#include "impact3d/mechanics/strategies/limits.hpp"
#include "impact3d/mechanics/stronge/integrate.hpp"

namespace impact3d {

// Why exact and certified arithmetic refuse it: its events are roots and its steps truncated series.
inline constexpr const char* kStrongeNotExact =
    "stronge has no exact or certified form: its impulse is an integral whose events are roots of "
    "transcendental equations; solve it at a floating precision (--precision 100 for 100 digits)";

// The strategy's entry (strategies/list.hpp): its parameters; its solve is strategies::solve below. It
// decides no regime from the inputs: sticking or not is an outcome of the integration.
template <typename Scalar>
struct Stronge {
  Scalar mu;
  stronge::RestitutionLaw law = stronge::RestitutionLaw::energetic;

  static constexpr std::string_view name = "stronge";
  static constexpr std::array<Parameter, 2> parameters{
      {{"mu", ParameterType::non_negative}, {"restitution", ParameterType::choice, stronge::law_names}}};
  static constexpr std::string_view friction_key = "mu";
  // verify's random draws: a range of friction, each collision's law drawn among the three (one draw a
  // collision, for the 100-digit integrations are most of verify's time). verify holds it to the
  // 100-digit solve within the two integrations' stated bounds and the rounding of K: it has no
  // fractions or enclosures to check against.
  static constexpr std::array<std::array<ParameterDraw, 2>, 1> verified{{{{{0, 1.2}, {}}}}};
  static constexpr bool solves_full_impact = false;
  static constexpr std::array<const char*, 0> regime_decisions{};

  template <typename Values>
  static Stronge make(const Values& v) {
    return {*v.number("mu"), static_cast<stronge::RestitutionLaw>(v.choice_index("restitution"))};
  }
  template <typename To, typename F>
  Stronge<To> convert(F&& f) const {
    return {f(mu), law};
  }
  std::optional<RegimeDecision<Scalar>> regime_decision() const { return std::nullopt; }
};

}  // namespace impact3d

namespace impact3d::strategies {

// Fills `out` (with the history when it is for a report); returns why the impact could not be followed,
// if it could not. Exact and enclosure arithmetic throw kStrongeNotExact.
template <typename Engine, typename Scalar>
Singular solve(const Problem<Scalar>& p, const Stronge<Scalar>& spec, ImpulseSolution<Scalar>& out) {
  if constexpr (is_exact_v<Scalar> || is_enclosure_v<Scalar>) {
    throw SolveError(kStrongeNotExact);
  } else {
    stronge::History<Scalar> h = stronge::integrate<Scalar, typename Engine::StrongeForms>(
        p.K, p.m_prime, p.V_ri, spec.mu, p.restitution, spec.law, out.for_report);
    if (h.failure) return {h.failure, true};
    out.P_C = h.P_C;
    out.mu = plane_length(out.P_C.y(), out.P_C.z()) / out.P_C.x();  // at most mu: less once it sticks
    out.mu_t = out.P_C.y() / out.P_C.x();
    out.mu_z = out.P_C.z() / out.P_C.x();
    out.regime = h.final_direction_deg ? Regime::sliding : Regime::full;
    flag_if_not_finite(out, *out.mu, "mu");
    flag_if_not_finite(out, *out.mu_t, "mu_t");
    flag_if_not_finite(out, *out.mu_z, "mu_z");
    out.integration_error = h.relative_error;
    if (out.for_report) out.history = std::move(h);
    return {};
  }
}

}  // namespace impact3d::strategies
