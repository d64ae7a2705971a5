// The contact-plane part of eq 9 while the contact slides or sticks, in Stronge's variables: with the
// normal impulse p as the independent variable and the tangential impulse rate f = dP_tz/dp,
//   m' du/dp = -(k + A f),   u = (V_t, V_z),
// k = (K_tn, K_zn) the normal column's tangential part and A = [[K_tt, K_tz], [K_zt, K_zz]] the
// tangential block. Sliding: f = mu u/|u|; sticking: f = r with A r = -k, the ratio that keeps u = 0;
// resuming from rest: f = mu d along a direction d that the map carries onto itself, outward. The stop
// series (stop_series.hpp) reads k and A; the decisions go through the engine's forms
// (generated_forms.hpp, direct/stronge_forms.hpp).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "impact3d/mechanics/stronge/real_roots.hpp"
#include "impact3d/scalar/types.hpp"

namespace impact3d::stronge {

template <typename Scalar>
struct TangentialMap {
  Scalar k_t, k_z;          // K_tn, K_zn
  Scalar A_tt, A_tz, A_zz;  // the tangential block (K symmetric)

  static TangentialMap of(const Mat3<Scalar>& K) {
    // K is symmetric (problem.hpp); its mean off-diagonal keeps a rounded K's map symmetric.
    return {K(1, 0), K(2, 0), K(1, 1), Scalar((K(1, 2) + K(2, 1)) / Scalar(2)), K(2, 2)};
  }
};

template <typename Scalar>
struct Direction {
  Scalar c, s;      // unit vector (t, z)
  Scalar growth;    // d|u|/dp m' along it: > 0 outward
};

// Every invariant direction of the map at friction mu: the unit vectors d with (k + mu A d) x d = 0.
// With d at angle theta the condition is a trigonometric polynomial of degree 2,
//   k_t s - k_z c + mu ((A_tt - A_zz) c s + A_tz (s^2 - c^2)) = 0,
// which the half-angle t = tan(phi / 2), theta = theta_0 + phi, turns into a quartic (the engine's
// Forms, generated_forms.hpp); theta_0 is the direction of a fixed rational set whose opposite is
// farthest from a root, so that none is lost at t = infinity. Empty when the condition vanishes
// identically (k = 0 and A isotropic: every direction is invariant and none outward).
template <typename Forms, typename Scalar>
std::vector<Direction<Scalar>> invariant_directions(const Mat3<Scalar>& K, const Scalar& mu) {
  using std::abs;
  const std::array<std::array<int, 2>, 8> rational{{{5, 0}, {0, 5}, {-5, 0}, {0, -5}, {3, 4}, {-4, 3}, {-3, -4}, {4, -3}}};
  Scalar best(-1), c0(1), s0(0);
  for (const auto& v : rational) {
    const Scalar c = ratio<Scalar>(v[0], 5), s = ratio<Scalar>(v[1], 5);
    const Scalar at_opposite = abs(Forms::direction_rates(K, mu, Scalar(-c), Scalar(-s))[1]);
    if (at_opposite > best) best = at_opposite, c0 = c, s0 = s;
  }
  const Scalar scale = abs(K(1, 0)) + abs(K(2, 0)) + mu * (abs(K(1, 1)) + abs(K(2, 2)) + abs(K(1, 2)));
  const Scalar zero = Scalar(64) * std::numeric_limits<Scalar>::epsilon() * scale;
  if (!(best > zero)) return {};
  const std::array<Scalar, 5> q = Forms::invariant_quartic(K, mu, c0, s0);
  std::vector<Direction<Scalar>> out;
  for (const Scalar& t : real_roots(std::vector<Scalar>(q.begin(), q.end()), zero)) {
    const Scalar q1 = Scalar(1) + t * t;
    const Scalar cp = (Scalar(1) - t * t) / q1, sp = Scalar(2) * t / q1;
    const Scalar c = c0 * cp - s0 * sp, s = s0 * cp + c0 * sp;
    out.push_back({c, s, Forms::direction_rates(K, mu, c, s)[0]});
  }
  return out;
}

}  // namespace impact3d::stronge
