// The direct engine's forms of the sliding map (stronge/generated_forms.hpp names them), by a route apart
// from the generated kernels: the stick ratio a 3x3 solve of constraint rows (dP_n = 1, no change of V_t
// or V_z), the rates K times the impulse rate, and the invariant directions' quartic derived by hand.
#pragma once

#include <array>
#include <optional>

#include "impact3d/mechanics/direct/constraints.hpp"

namespace impact3d::direct {

struct StrongeForms {
  template <typename Scalar>
  static std::optional<std::array<Scalar, 2>> stick_ratio(const Mat3<Scalar>& K) {
    const Vec3<Scalar> n = Vec3<Scalar>::UnitX(), t = Vec3<Scalar>::UnitY(), z = Vec3<Scalar>::UnitZ();
    const auto P = solve_rows<Scalar>({Row<Scalar>{n, Scalar(1)}, Row<Scalar>{K.transpose() * t, Scalar(0)},
                                      Row<Scalar>{K.transpose() * z, Scalar(0)}});
    if (!P) return std::nullopt;
    return std::array<Scalar, 2>{(*P)(1), (*P)(2)};
  }
  template <typename Scalar>
  static std::array<Scalar, 2> direction_rates(const Mat3<Scalar>& K, const Scalar& mu, const Scalar& c, const Scalar& s) {
    const Vec3<Scalar> du = -(K * Vec3<Scalar>(Scalar(1), Scalar(mu * c), Scalar(mu * s)));
    return {Scalar(du(1) * c + du(2) * s), Scalar(du(2) * c - du(1) * s)};
  }
  // The turning k_t s - k_z c + mu ((A_tt - A_zz) c s + A_tz (s^2 - c^2)) as a1 sin + b1 cos + a2 sin 2th
  // + b2 cos 2th, rotated by theta_0, times (1 + t^2)^2 with sin phi = 2t / (1 + t^2), cos phi =
  // (1 - t^2) / (1 + t^2).
  template <typename Scalar>
  static std::array<Scalar, 5> invariant_quartic(const Mat3<Scalar>& K, const Scalar& mu, const Scalar& c0, const Scalar& s0) {
    const Scalar A_tz = (K(1, 2) + K(2, 1)) / Scalar(2);
    const Scalar a1 = K(1, 0), b1 = -K(2, 0), a2 = mu * (K(1, 1) - K(2, 2)) / Scalar(2), b2 = -mu * A_tz;
    const Scalar c2 = c0 * c0 - s0 * s0, s2 = Scalar(2) * s0 * c0;
    const Scalar a1r = a1 * c0 - b1 * s0, b1r = a1 * s0 + b1 * c0;
    const Scalar a2r = a2 * c2 - b2 * s2, b2r = a2 * s2 + b2 * c2;
    return {Scalar(b1r + b2r), Scalar(Scalar(2) * a1r + Scalar(4) * a2r), Scalar(Scalar(-6) * b2r),
            Scalar(Scalar(2) * a1r - Scalar(4) * a2r), Scalar(b2r - b1r)};
  }
};

}  // namespace impact3d::direct
