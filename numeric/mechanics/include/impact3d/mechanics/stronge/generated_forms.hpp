// The three forms of the sliding map the integration decides by: the stick ratio (the impulse ratio that
// keeps a stopped contact stuck), the rates of a slide along a direction (its speed's growth and its
// turning) and the quartic whose roots are the invariant directions. These are the generated engine's,
// GiNaC's kernels (generated/stronge.hpp); the direct engine has its own (direct/stronge_forms.hpp), so
// that the two engines integrate by two routes.
#pragma once

#include <array>
#include <optional>

#include "impact3d/generated/stronge.hpp"
#include "impact3d/scalar/exact.hpp"
#include "impact3d/scalar/types.hpp"

namespace impact3d::stronge {

struct GeneratedForms {
  template <typename Scalar>
  static std::optional<std::array<Scalar, 2>> stick_ratio(const Mat3<Scalar>& K) {
    const auto r = generated::stronge_stick_ratio(K);
    if (!is_finite(Scalar(r(0))) || !is_finite(Scalar(r(1)))) return std::nullopt;
    return std::array<Scalar, 2>{r(0), r(1)};
  }
  // (m' d|u|/dp, m' |u| dtheta/dp) sliding along the unit vector (c, s).
  template <typename Scalar>
  static std::array<Scalar, 2> direction_rates(const Mat3<Scalar>& K, const Scalar& mu, const Scalar& c, const Scalar& s) {
    const auto r = generated::stronge_direction_rates(K, mu, c, s);
    return {r(0), r(1)};
  }
  template <typename Scalar>
  static std::array<Scalar, 5> invariant_quartic(const Mat3<Scalar>& K, const Scalar& mu, const Scalar& c0, const Scalar& s0) {
    const auto q = generated::stronge_invariant_quartic(K, mu, c0, s0);
    return {q(0), q(1), q(2), q(3), q(4)};
  }
};

}  // namespace impact3d::stronge
