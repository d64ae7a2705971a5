// The Taylor series of a slide coming to rest, in the time-like variable tau with dx = |u| dtau
// (x = p / (m' v0), sliding_series.hpp). In x the sliding direction u / |u| near a 3D stop is a
// non-integer power of the distance to it, so steps in x only approach the stop geometrically; in tau
//   dx/dtau = |u|,   da/dtau = mu u_t,   db/dtau = mu u_z,   dW/dtau = U_n |u|,
// with U = U_i - K (x, a, b), is homogeneous of degree one in u and regular: the stop is tau -> infinity,
// |u| falls exponentially and the direction settles on an invariant direction (tangential_map.hpp).
// No division by |u|: only its square root's recurrence (speed_coefficient, sliding_series.hpp).
#pragma once

#include <cmath>
#include <vector>

#include "impact3d/mechanics/stronge/sliding_series.hpp"

namespace impact3d::stronge {

template <typename Scalar>
struct ApproachSeries {
  // Coefficients 0..order of each quantity in tau - tau0.
  std::vector<Scalar> x, a, b, W, U_n, u_t, u_z;
};

// sum_{i <= j} p_i q_{j - i}, in four running sums, for one would wait on each addition's latency.
template <typename Scalar>
Scalar convolution(const std::vector<Scalar>& p, const std::vector<Scalar>& q, std::size_t j) {
  Scalar w0(0), w1(0), w2(0), w3(0);
  std::size_t i = 0;
  for (; i + 3 <= j; i += 4) {
    w0 += p[i] * q[j - i], w1 += p[i + 1] * q[j - i - 1];
    w2 += p[i + 2] * q[j - i - 2], w3 += p[i + 3] * q[j - i - 3];
  }
  for (; i <= j; ++i) w0 += p[i] * q[j - i];
  return (w0 + w1) + (w2 + w3);
}

// The series about (x0, a0, b0, W0) to `order`, with the sliding velocity u0 there (carried by the steps:
// U_i - K P loses its relative accuracy as u falls towards rounding); u0 must not be zero.
// Into `s`, whose vectors (and the speed's, r) keep their storage from one step to the next.
template <typename Scalar>
void approach_series_into(ApproachSeries<Scalar>& s, std::vector<Scalar>& r, const Mat3<Scalar>& K, const Vec3<Scalar>& U_i,
                          const Scalar& mu, const Scalar& x0, const Scalar& a0, const Scalar& b0, const Scalar& W0,
                          const Scalar& u0_t, const Scalar& u0_z, int order) {
  const std::size_t n = static_cast<std::size_t>(order) + 1;
  for (auto* v : {&s.x, &s.a, &s.b, &s.W, &s.U_n, &s.u_t, &s.u_z, &r}) v->assign(n, Scalar(0));
  s.x[0] = x0, s.a[0] = a0, s.b[0] = b0, s.W[0] = W0;
  Scalar half_over_r0(0);
  for (std::size_t j = 0; j < n; ++j) {
    for (int row = 0; row < 3; ++row) {
      Scalar c = -(K(row, 0) * s.x[j] + K(row, 1) * s.a[j] + K(row, 2) * s.b[j]);
      if (j == 0) c += U_i(row);
      (row == 0 ? s.U_n : row == 1 ? s.u_t : s.u_z)[j] = c;
    }
    if (j == 0) s.u_t[0] = u0_t, s.u_z[0] = u0_z;
    r[j] = speed_coefficient(s.u_t, s.u_z, r, j, half_over_r0);
    if (j == 0) half_over_r0 = Scalar(1) / (Scalar(2) * r[0]);
    if (j + 1 == n) break;
    const Scalar over_k = Scalar(1) / Scalar(static_cast<long long>(j + 1));
    s.x[j + 1] = r[j] * over_k;
    s.a[j + 1] = mu * s.u_t[j] * over_k;
    s.b[j + 1] = mu * s.u_z[j] * over_k;
    s.W[j + 1] = convolution(s.U_n, r, j) * over_k;
  }
}

template <typename Scalar>
ApproachSeries<Scalar> approach_series(const Mat3<Scalar>& K, const Vec3<Scalar>& U_i, const Scalar& mu,
                                       const Scalar& x0, const Scalar& a0, const Scalar& b0, const Scalar& W0,
                                       const Scalar& u0_t, const Scalar& u0_z, int order) {
  ApproachSeries<Scalar> s;
  std::vector<Scalar> r;
  approach_series_into(s, r, K, U_i, mu, x0, a0, b0, W0, u0_t, u0_z, order);
  return s;
}

}  // namespace impact3d::stronge
