// What each engine offers beside its primitives: the throwing form of each, for the callers that have no
// use for a singular system (the figures, the impulse-space geometry, the tools). An engine E derives
// from EnginePrimitives<E> and defines try_full_impact, try_plane_ratio, try_plane_impulse,
// try_brach_impulse (empty where its system is singular) and singular_reason.
#pragma once

#include <optional>
#include <string>

#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/strategy.hpp"

namespace impact3d {

template <typename E>
struct EnginePrimitives {
  // The error for a singular constraint system `what`, in this engine's words.
  static SolveError singular(const std::string& what) {
    return SolveError(what + ": the constraints admit no unique impulse (" + E::singular_reason + ")");
  }
  template <typename T>
  static T required(const std::optional<T>& x, const std::string& what) {
    if (!x) throw singular(what);
    return *x;
  }
  template <typename Scalar>
  static Vec3<Scalar> full_impact(const Problem<Scalar>& p, const Scalar& eps) {
    return required(E::try_full_impact(p, eps), "full impact");
  }
  template <typename Scalar>
  static Scalar plane_ratio(const Problem<Scalar>& p, const PlaneAxes<Scalar>& ax, const Scalar& eps,
                            const std::string& what) {
    return required(E::try_plane_ratio(p, ax, eps), what);
  }
  template <typename Scalar>
  static Vec3<Scalar> plane_impulse(const Problem<Scalar>& p, const PlaneAxes<Scalar>& ax, const Scalar& mu,
                                    const std::string& what) {
    return required(E::try_plane_impulse(p, ax, mu), what);
  }
  template <typename Scalar>
  static Vec3<Scalar> brach_impulse(const Problem<Scalar>& p, const std::optional<Scalar>& mu_t,
                                    const std::optional<Scalar>& mu_z, const std::string& what) {
    return required(E::try_brach_impulse(p, mu_t, mu_z), what);
  }
};

}  // namespace impact3d
