// The generated engine: the adapter between the library's types and the kernels that symbolic/ derives
// and writes into generated/ (do not edit those; regenerate). A closed form divides where the direct
// engine's 3x3 system is singular: each primitive returns nothing for a non-finite result, and its
// throwing form (for the figures and the tools) a SolveError naming the constraint.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include "impact3d/generated/brach.hpp"
#include "impact3d/generated/coefficient_matrix.hpp"
#include "impact3d/generated/full_impact.hpp"
#include "impact3d/generated/solution_plane.hpp"
#include "impact3d/mechanics/engine_primitives.hpp"
#include "impact3d/scalar/exact.hpp"
#include "impact3d/mechanics/kinematics.hpp"
#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/strategy.hpp"
#include "impact3d/mechanics/stronge/generated_forms.hpp"

namespace impact3d {

struct GeneratedEngine : EnginePrimitives<GeneratedEngine> {
  static constexpr const char* singular_reason = "a closed form divides by zero";
  using StrongeForms = stronge::GeneratedForms;

  template <typename Scalar>
  static Mat3<Scalar> coefficient_matrix(const Scene<Scalar>& s) {
    return generated::coefficient_matrix(reduced_mass(s), s.body[0].J_B, s.body[1].J_B, s.body[0].p_CgIc_B,
                                         s.body[1].p_CgIc_B, R_CB(s, 0), R_CB(s, 1));
  }
  template <typename Scalar>
  static std::optional<Vec3<Scalar>> try_full_impact(const Problem<Scalar>& p, const Scalar& eps) {
    return finite(generated::full_impact(p.K, p.m_prime, eps, p.V_ri));
  }
  template <typename Scalar>
  static std::optional<Scalar> try_plane_ratio(const Problem<Scalar>& p, const PlaneAxes<Scalar>& ax, const Scalar& eps) {
    return finite(eps == Scalar(0) ? generated::plane_generalized_ratio(p.K, p.V_ri, ax.c, ax.s)
                                   : generated::plane_critical_ratio(p.K, eps, p.V_ri, ax.c, ax.s));
  }
  template <typename Scalar>
  static std::optional<Vec3<Scalar>> try_plane_impulse(const Problem<Scalar>& p, const PlaneAxes<Scalar>& ax,
                                                       const Scalar& mu) {
    return finite(generated::plane_impulse(p.K, p.m_prime, p.restitution, p.V_ri, ax.c, ax.s, mu));
  }
  template <typename Scalar>
  static std::optional<Vec3<Scalar>> try_brach_impulse(const Problem<Scalar>& p, const std::optional<Scalar>& mu_t,
                                                       const std::optional<Scalar>& mu_z) {
    Scalar t, z;
    if (mu_t && mu_z) {
      t = *mu_t;
      z = *mu_z;
    } else if (mu_z) {  // eq 25
      t = generated::brach_critical_t(p.K, p.restitution, p.V_ri, *mu_z);
      z = *mu_z;
    } else if (mu_t) {  // eq 26
      t = *mu_t;
      z = generated::brach_critical_z(p.K, p.restitution, p.V_ri, *mu_t);
    } else {  // eq 27
      const auto both = generated::brach_critical_both(p.K, p.restitution, p.V_ri);
      t = both(0);
      z = both(1);
    }
    if (!is_finite(t) || !is_finite(z)) return std::nullopt;
    return finite(generated::brach_impulse(p.K, p.m_prime, p.restitution, p.V_ri, t, z));
  }

 private:
  template <typename Scalar>
  static std::optional<Scalar> finite(const Scalar& x) {
    if (!is_finite(x)) return std::nullopt;
    return x;
  }
  template <typename Scalar>
  static std::optional<Vec3<Scalar>> finite(const Vec3<Scalar>& v) {
    if (!all_finite(v)) return std::nullopt;
    return v;
  }
};

}  // namespace impact3d
