// The lean solve: one strategy of one collision, computing only what the caller wants (the impulse, or
// the impulse and the post-impact velocities), with no heap allocation and no exception for an ordinary
// outcome (bodies that do not approach, a singular constraint system): a status instead. The condition
// of K and the amplification of rounding are bounded cheaply and computed only when a decision falls
// within the bound (Problem::settle). analyze (analysis.hpp) solves each strategy by the same
// solve_strategy and decides alike; it adds what only a report needs.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <variant>

#include "impact3d/mechanics/direct/engine.hpp"
#include "impact3d/mechanics/generated_engine.hpp"
#include "impact3d/scalar/lean_twin.hpp"
#include "impact3d/mechanics/post_impact.hpp"
#include "impact3d/mechanics/precision_warnings.hpp"
#include "impact3d/mechanics/raw_collision.hpp"
#include "impact3d/scalar/scalars.hpp"
#include "impact3d/mechanics/strategies/list.hpp"

namespace impact3d {

// A strategy's impulse into `out`; the singular constraint system, if any.
template <typename E, typename Scalar>
Singular solve_strategy(const Problem<Scalar>& p, const Strategy<Scalar>& st, ImpulseSolution<Scalar>& out) {
  return std::visit([&](const auto& s) { return strategies::solve<E>(p, s, out); }, st);
}

enum class Want : std::uint8_t { impulse, velocities };

enum class Status : std::uint8_t { solved, not_approaching, singular };

inline const char* status_name(Status s) {
  switch (s) {
    case Status::solved: return "solved";
    case Status::not_approaching: return "not approaching";
    case Status::singular: return "singular";
  }
  return "?";
}

template <typename Scalar>
struct LeanSolution {
  Status status = Status::solved;
  const char* singular = nullptr;   // the singular constraint system, when status is singular
  ImpulseSolution<Scalar> impulse;  // P_C, the regime, the ratios and limits (no text, no plane angle)
  // Every warning analyze would give this impulse but energy_gained, which needs the energies: the
  // strategy's, tensile_normal_impulse, not_finite, rounding. not_finite concerns what was computed (the
  // impulse, its ratios, m', K, V_ri, and the velocities when wanted), not analyze's impulse-space
  // geometry.
  WarningSet warnings = 0;
  // Want::velocities: the impulse on vehicle 1 in world axes and the post-impact states.
  Vec3<Scalar> P_W;
  std::array<Vec3<Scalar>, 2> v_W, w_B;  // CG velocity (world), angular velocity (body)
};

template <typename E, typename Scalar>
LeanSolution<Scalar> solve_lean_with(const Scene<Scalar>& s, const Strategy<Scalar>& st, Want want) {
  LeanSolution<Scalar> out;
  out.impulse.for_report = false;
  const Problem<Scalar> p = make_problem<E>(s, true);
  if (!approaching(p)) {
    out.status = Status::not_approaching;
    return out;
  }
  // analyze takes the maximum-energy-loss impulse (eps = 0) for the impulse space before any strategy,
  // and refuses the case where it is singular. A strategy that solves the Full Impact first (pc-crash)
  // has the same matrix.
  const bool solves_full_impact = std::visit([](const auto& s) { return s.solves_full_impact; }, st);
  if (!solves_full_impact && !E::try_full_impact(p, Scalar(0))) {
    out.status = Status::singular;
    out.singular = "full impact";
    return out;
  }
  if (const Singular f = solve_strategy<E>(p, st, out.impulse)) {
    out.status = Status::singular;
    out.singular = f.what;
    return out;
  }
  WarningSet w = out.impulse.codes;
  const Vec3<Scalar>& P = out.impulse.P_C;
  if (!(P.x() > Scalar(0))) w |= warning_bit(WarningCode::tensile_normal_impulse);
  bool finite = all_finite(P) && is_finite(p.m_prime) && all_finite(p.K) && all_finite(p.V_ri);
  for (const auto* ratio : {&out.impulse.mu, &out.impulse.mu_t, &out.impulse.mu_z})
    finite = finite && (!*ratio || is_finite(**ratio));
  if (want == Want::velocities) {
    out.P_W = s.R_WC * P;
    const Vec3<Scalar> minus_P_W = -out.P_W;
    for (int i = 0; i < 2; ++i) {
      const RigidBody<Scalar> after = apply_impulse(s.body[i], i == 0 ? out.P_W : minus_P_W);
      out.v_W[i] = after.v_W;
      out.w_B[i] = after.w_B;
      finite = finite && all_finite(after.v_W) && all_finite(after.w_B);
    }
  }
  if (!finite) w |= warning_bit(WarningCode::not_finite);
  if constexpr (!is_exact_v<Scalar>) {
    // Decided on the bound when it is at most half the trusted fraction, else on the settled value.
    const Scalar integration = out.impulse.integration_error ? *out.impulse.integration_error : Scalar(0);
    if (!(Scalar(rounding_bound_of(p.amplification_bound, p.quotient) + integration) <=
          Scalar(rounding::kTrustedFraction / 2))) {
      p.settle();
      if (!trusted(Scalar(rounding_bound_of(p.amplification, p.quotient) + integration)))
        w |= warning_bit(WarningCode::rounding);
    }
  }
  out.warnings = w;
  return out;
}

// A lean solution's numbers by f (a scalar to its twin and back, lean_twin.hpp).
// The velocities only when wanted: else they are zeros on both sides.
template <typename To, typename From, typename F>
LeanSolution<To> convert_solution(const LeanSolution<From>& in, Want want, F&& f) {
  auto opt = [&](const std::optional<From>& x) { return x ? std::optional<To>(f(*x)) : std::nullopt; };
  LeanSolution<To> out;
  out.status = in.status, out.singular = in.singular, out.warnings = in.warnings;
  const ImpulseSolution<From>& a = in.impulse;
  ImpulseSolution<To>& b = out.impulse;
  b.P_C = convert_each<To>(a.P_C, f);
  b.regime = a.regime;
  b.mu = opt(a.mu), b.mu_t = opt(a.mu_t), b.mu_z = opt(a.mu_z);
  b.gir = opt(a.gir), b.cir = opt(a.cir), b.mu_t_critical = opt(a.mu_t_critical), b.mu_z_critical = opt(a.mu_z_critical);
  if (a.plane) b.plane = PlaneAxes<To>{f(a.plane->c), f(a.plane->s)};
  b.plane_angle_deg = opt(a.plane_angle_deg);
  b.integration_error = opt(a.integration_error);
  b.codes = a.codes, b.for_report = a.for_report;
  if (want == Want::impulse) return out;
  out.P_W = convert_each<To>(in.P_W, f);
  for (int i = 0; i < 2; ++i) out.v_W[i] = convert_each<To>(in.v_W[i], f), out.w_B[i] = convert_each<To>(in.w_B[i], f);
  return out;
}

// The engine asked for at run time, chosen here alone.
template <typename Scalar>
LeanSolution<Scalar> solve_lean_on(Engine engine, const Scene<Scalar>& s, const Strategy<Scalar>& st, Want want) {
  if (engine == Engine::direct) return solve_lean_with<direct::DirectEngine>(s, st, want);
  return solve_lean_with<GeneratedEngine>(s, st, want);
}

// A scene in the twin T of Scalar (lean_twin.hpp) solved there, the solution given in Scalar.
template <typename Scalar, typename T = lean_twin_t<Scalar>>
LeanSolution<Scalar> solve_lean_in_twin(const Scene<T>& s, const Strategy<Scalar>& st, Want want, Engine engine) {
  using Twin = LeanTwin<Scalar>;
  const Strategy<T> twin_strategy = convert_strategy<T>(st, [](const Scalar& x) { return Twin::to(x); });
  const LeanSolution<T> r = solve_lean_on(engine, s, twin_strategy, want);
  return convert_solution<Scalar>(r, want, [](const T& x) { return Twin::from(x); });
}

// The scene must outlive the call only; nothing is kept. A scalar with a lean twin (lean_twin.hpp) is
// solved in the twin, whose every operation gives the scalar's value: the same solution, faster.
// Throws std::invalid_argument when an inertia tensor is not symmetric (scene.hpp): a caller's mistake,
// not an outcome. From raw parameters (below) the upper triangle is read, and no check is needed.
template <typename Scalar>
LeanSolution<Scalar> solve_lean(const Scene<Scalar>& s, const Strategy<Scalar>& st, Want want = Want::impulse,
                                Engine engine = Engine::generated) {
  require_symmetric_inertia(s);
  if constexpr (has_lean_twin_v<Scalar>) {
    return solve_lean_in_twin(convert_scene<lean_twin_t<Scalar>>(s, [](const Scalar& x) { return LeanTwin<Scalar>::to(x); }),
                              st, want, engine);
  } else {
    return solve_lean_on(engine, s, st, want);
  }
}

// From raw parameters: solve_lean(scene_of(c), ...), the same solution. A scalar with a lean twin goes
// from the raw parameters to the solution in the twin, its scene not converted to the scalar and back
// (at 100 digits that was about 5 % of the instructions, BENCHMARKS.md).
template <typename Scalar>
LeanSolution<Scalar> solve_lean(const RawCollision<Scalar>& c, const Strategy<Scalar>& st, Want want = Want::impulse,
                                Engine engine = Engine::generated) {
  if constexpr (has_lean_twin_v<Scalar>) return solve_lean_in_twin(compute_scene(twin_of(c)), st, want, engine);
  else return solve_lean_on(engine, scene_of(c), st, want);
}

}  // namespace impact3d

namespace impact3d {
#define IMPACT3D_EXTERN_SOLVE_LEAN_(type, name, u) \
  extern template LeanSolution<type> solve_lean(const Scene<type>&, const Strategy<type>&, Want, Engine); \
  extern template LeanSolution<type> solve_lean(const RawCollision<type>&, const Strategy<type>&, Want, Engine);
IMPACT3D_SCALARS(IMPACT3D_EXTERN_SOLVE_LEAN_)
#undef IMPACT3D_EXTERN_SOLVE_LEAN_
}  // namespace impact3d
