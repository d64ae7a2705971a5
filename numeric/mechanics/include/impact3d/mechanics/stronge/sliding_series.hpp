// The Taylor series of a sliding contact about one normal impulse, to any order, by the recurrences of
// automatic differentiation (Jorba and Zou, Experiment. Math. 14 (2005) 99): the integration's one step.
//
// Dimensionless: x = p / (m' v0), P = (x, a, b) the impulse over m' v0, U = V / v0 with v0 = |V_ri|, so
// that eq 9 reads U = U_i - K P. Sliding (history.hpp, tangential_map.hpp):
//   da/dx = mu u_t / |u|,   db/dx = mu u_z / |u|,   dW/dx = U_n   (W the normal work over m' v0^2),
// u = (U_t, U_z) linear in (x, a, b). With h = x - x0 each quantity is a polynomial sum_j c_j h^j; the
// coefficients of |u|^2, |u| and u / |u| follow from those of u by Cauchy products.
#pragma once

#include <cmath>
#include <vector>

#include "impact3d/scalar/types.hpp"

namespace impact3d::stronge {

template <typename Scalar>
struct SlidingSeries {
  // Coefficients 0..order of each quantity in h.
  std::vector<Scalar> a, b, W, U_n, u_t, u_z;
};

// Coefficient j of |u| from u's coefficients 0..j and |u|'s 0..j-1: |u|^2 by a Cauchy product, whose
// coefficient j is 2 r_0 r_j plus the cross terms; `half_over_r0` is 1 / (2 r_0), taken once a series
// (a division on every coefficient's path would wait for the one before). Both kinds of step (this
// file, approach_series.hpp).
template <typename Scalar>
Scalar speed_coefficient(const std::vector<Scalar>& u_t, const std::vector<Scalar>& u_z, const std::vector<Scalar>& r,
                         std::size_t j, const Scalar& half_over_r0) {
  using std::sqrt;
  if (j == 0) return sqrt(u_t[0] * u_t[0] + u_z[0] * u_z[0]);
  // Both sums are symmetric in i <-> j - i: each pair once, doubled, and the middle term of an even j.
  Scalar sq(0), cross(0);
  for (std::size_t i = 1; 2 * i < j; ++i) sq += u_t[i] * u_t[j - i] + u_z[i] * u_z[j - i], cross += r[i] * r[j - i];
  sq = Scalar(2) * (sq - cross + u_t[0] * u_t[j] + u_z[0] * u_z[j]);
  if (j % 2 == 0) sq += u_t[j / 2] * u_t[j / 2] + u_z[j / 2] * u_z[j / 2] - r[j / 2] * r[j / 2];
  return sq * half_over_r0;
}

// The series about (x0, a0, b0, W0) to `order`; u(x0) must not be zero.
template <typename Scalar>
SlidingSeries<Scalar> sliding_series(const Mat3<Scalar>& K, const Vec3<Scalar>& U_i, const Scalar& mu, const Scalar& x0,
                                     const Scalar& a0, const Scalar& b0, const Scalar& W0, int order) {
  const std::size_t n = static_cast<std::size_t>(order) + 1;
  SlidingSeries<Scalar> s;
  for (auto* v : {&s.a, &s.b, &s.W, &s.U_n, &s.u_t, &s.u_z}) v->assign(n, Scalar(0));
  std::vector<Scalar> r(n, Scalar(0)), q_t(n, Scalar(0)), q_z(n, Scalar(0));
  s.a[0] = a0, s.b[0] = b0, s.W[0] = W0;
  Scalar over_r0(0), half_over_r0(0);
  for (std::size_t j = 0; j < n; ++j) {
    // U = U_i - K (x, a, b): its coefficient j from a_j, b_j and x's (x0, then 1, then 0).
    for (int row = 0; row < 3; ++row) {
      Scalar c = -(K(row, 1) * s.a[j] + K(row, 2) * s.b[j]);
      if (j == 0) c += U_i(row) - K(row, 0) * x0;
      if (j == 1) c -= K(row, 0);
      (row == 0 ? s.U_n : row == 1 ? s.u_t : s.u_z)[j] = c;
    }
    r[j] = speed_coefficient(s.u_t, s.u_z, r, j, half_over_r0);
    if (j == 0) over_r0 = Scalar(1) / r[0], half_over_r0 = over_r0 / Scalar(2);
    Scalar qt = s.u_t[j], qz = s.u_z[j];
    for (std::size_t i = 1; i <= j; ++i) qt -= r[i] * q_t[j - i], qz -= r[i] * q_z[j - i];
    q_t[j] = qt * over_r0, q_z[j] = qz * over_r0;
    if (j + 1 < n) {
      const Scalar over_next = Scalar(1) / Scalar(static_cast<long long>(j + 1));
      s.a[j + 1] = mu * q_t[j] * over_next;
      s.b[j + 1] = mu * q_z[j] * over_next;
      s.W[j + 1] = s.U_n[j] * over_next;
    }
  }
  return s;
}

}  // namespace impact3d::stronge
