// The direct engine's primitives: K assembled numerically, every impulse a 3x3 solve of constraint rows.
#pragma once

#include <optional>

#include "impact3d/mechanics/direct/coefficient_matrix.hpp"
#include "impact3d/mechanics/direct/constraints.hpp"
#include "impact3d/mechanics/direct/full_impact.hpp"
#include "impact3d/mechanics/direct/stronge_forms.hpp"
#include "impact3d/mechanics/engine_primitives.hpp"

namespace impact3d::direct {

struct DirectEngine : EnginePrimitives<DirectEngine> {
  static constexpr const char* singular_reason = "singular system";
  using StrongeForms = direct::StrongeForms;

  template <typename Scalar>
  static Mat3<Scalar> coefficient_matrix(const Scene<Scalar>& s) {
    return direct::coefficient_matrix(s);
  }
  template <typename Scalar>
  static std::optional<Vec3<Scalar>> try_full_impact(const Problem<Scalar>& p, const Scalar& eps) {
    return full_impact_impulse(p, eps);
  }
  template <typename Scalar>
  static std::optional<Scalar> try_plane_ratio(const Problem<Scalar>& p, const PlaneAxes<Scalar>& ax, const Scalar& eps) {
    return plane_critical_ratio(p, ax, eps);
  }
  template <typename Scalar>
  static std::optional<Vec3<Scalar>> try_plane_impulse(const Problem<Scalar>& p, const PlaneAxes<Scalar>& ax,
                                                       const Scalar& mu) {
    return direct::plane_impulse(p, ax, mu);
  }
  // Ratios along t and z, each given or (empty) critical.
  template <typename Scalar>
  static std::optional<Vec3<Scalar>> try_brach_impulse(const Problem<Scalar>& p, const std::optional<Scalar>& mu_t,
                                                       const std::optional<Scalar>& mu_z) {
    const Vec3<Scalar> e_t = Vec3<Scalar>::UnitY(), e_z = Vec3<Scalar>::UnitZ();
    auto axis_row = [&](const Vec3<Scalar>& e, const std::optional<Scalar>& mu) {
      return mu ? ratio_row(e, *mu) : no_sliding_row(p, e);
    };
    return solve_rows<Scalar>({restitution_row(p, p.restitution), axis_row(e_t, mu_t), axis_row(e_z, mu_z)});
  }
};

}  // namespace impact3d::direct
