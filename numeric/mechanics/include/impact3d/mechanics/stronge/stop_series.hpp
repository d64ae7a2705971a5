// The rest of a slide that comes to rest, in closed form: a series in the angle between the sliding
// direction and the invariant direction it settles on.
//
// In tau (approach_series.hpp) with u = rho (cos th, sin th) the slide is
//   d rho / d tau = rho g(th),   d th / d tau = f(th),   dP / d tau = rho v(th),   v = (1, mu cos, mu sin),
// g the map's growth and f its turning (tangential_map.hpp), both free of rho: the equations are
// homogeneous of degree one. So the impulse still to come before the contact stops is rho F(th), with
//   f F' + g F = -v,
// and the normal work still to come is U_n(stop) rho F_x + rho^2 G(th) with
//   f G' + 2 g G = -K_n . F
// (K_n the normal row of K). About a direction th* where f vanishes, attracting (f' < 0) and shrinking
// (g < 0), both have a bounded solution, analytic in delta = th - th*: with f = sum f_j delta^j
// (f_0 = 0) and likewise g, v, the coefficient n of the first equation gives
//   (n f_1 + g_0) F_n = -v_n - sum_{j=2}^{n+1} (n + 1 - j) f_j F_{n+1-j} - sum_{j=1}^{n} g_j F_{n-j},
// where n f_1 + g_0 < 0 never vanishes; G likewise with 2 g. The series of cos(th* + delta) and
// cos(2 th* + 2 delta) are the derivatives' cycle; f and g are linear in them.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "impact3d/mechanics/stronge/tangential_map.hpp"

namespace impact3d::stronge {

template <typename Scalar>
struct StopTail {
  Vec3<Scalar> F;  // impulse still to come over rho
  Scalar G;        // the normal work's part quadratic in rho, over rho^2
  Scalar last;     // the two last terms' magnitude: the truncation's estimate
  // Between th* and th* + delta: K_n . F differs from K_n . F_0 by at most normal_variation, and the
  // growth g stays below zero when `shrinking` (so rho only falls on the way).
  Scalar KnF0, normal_variation;
  bool shrinking = false;
  bool converged = false;
  // The coefficients used, and f's and g's, for the path on the way (rest_at).
  std::vector<std::array<Scalar, 3>> F_n;
  std::vector<Scalar> G_n, f_n, g_n;
};

// On the way: at the angle delta_i between delta and 0, rho_i / rho (rho falls as the direction
// turns: d ln rho / d delta = g / f = h(delta) / delta, h = g / (f / delta) analytic, so
// ln(rho_i / rho) = h_0 ln(delta_i / delta) + sum_{n>=1} h_n (delta_i^n - delta^n) / n) and the rest
// from there, F(delta_i) and G(delta_i), hs = radius_series(t). Only for a converged tail with delta != 0
// and f_1 < 0.
// h's coefficients, once for every rest_at of a tail.
template <typename Scalar>
std::vector<Scalar> radius_series(const StopTail<Scalar>& t) {
  const std::size_t N = t.F_n.size();
  std::vector<Scalar> hs(N);
  for (std::size_t n = 0; n < N; ++n) {
    Scalar r = t.g_n[n];
    for (std::size_t j = 1; j <= n; ++j) r -= t.f_n[j + 1] * hs[n - j];
    hs[n] = r / t.f_n[1];
  }
  return hs;
}

template <typename Scalar>
std::array<Scalar, 5> rest_at(const StopTail<Scalar>& t, const std::vector<Scalar>& hs, const Scalar& delta,
                              const Scalar& delta_i) {
  using std::exp;
  using std::log;
  const std::size_t N = t.F_n.size();
  Scalar ln_ratio = hs[0] * log(Scalar(delta_i / delta)), p_i(1), p(1);
  Vec3<Scalar> F = Vec3<Scalar>::Zero();
  Scalar G(0);
  for (std::size_t n = 0; n < N; ++n) {
    if (n) {
      p_i *= delta_i, p *= delta;
      ln_ratio += hs[n] * (p_i - p) / Scalar(static_cast<long long>(n));
    }
    F += Vec3<Scalar>(t.F_n[n][0], t.F_n[n][1], t.F_n[n][2]) * p_i;
    G += t.G_n[n] * p_i;
  }
  return {Scalar(exp(ln_ratio)), F(0), F(1), F(2), G};
}

// The tail at delta from the direction (c, s) = th*, to the first order whose last two terms are
// `tolerance` of the sum, at most `max_order`; not converged when the terms do not fall that far.
template <typename Scalar>
StopTail<Scalar> stop_tail(const Mat3<Scalar>& K, const TangentialMap<Scalar>& m, const Scalar& mu, const Scalar& c,
                           const Scalar& s, const Scalar& delta, const Scalar& tolerance, int max_order) {
  using std::abs;
  const std::size_t N = static_cast<std::size_t>(max_order) + 1;
  // cos and sin of th* + delta and of 2 th* + 2 delta, coefficient n: the n-th derivative over n!; to
  // N, for F_{N-1}'s recurrence reads f_N.
  std::vector<Scalar> C(N + 1), S(N + 1), C2(N + 1), S2(N + 1);
  const Scalar c2 = c * c - s * s, s2 = Scalar(2) * c * s;
  Scalar factorial(1), twos(1);
  for (std::size_t n = 0; n <= N; ++n) {
    if (n) factorial *= Scalar(static_cast<long long>(n)), twos *= Scalar(2);
    const Scalar w = Scalar(1) / factorial, w2 = twos / factorial;
    switch (n % 4) {
      case 0: C[n] = c * w, S[n] = s * w, C2[n] = c2 * w2, S2[n] = s2 * w2; break;
      case 1: C[n] = -s * w, S[n] = c * w, C2[n] = -s2 * w2, S2[n] = c2 * w2; break;
      case 2: C[n] = -c * w, S[n] = -s * w, C2[n] = -c2 * w2, S2[n] = -s2 * w2; break;
      default: C[n] = s * w, S[n] = -c * w, C2[n] = s2 * w2, S2[n] = -c2 * w2; break;
    }
  }
  // turning = k_t s - k_z c + mu ((A_tt - A_zz) / 2 sin 2th - A_tz cos 2th),
  // growth = -(k_t c + k_z s + mu ((A_tt + A_zz) / 2 + (A_tt - A_zz) / 2 cos 2th + A_tz sin 2th)).
  const Scalar half_diff = (m.A_tt - m.A_zz) / Scalar(2), half_sum = (m.A_tt + m.A_zz) / Scalar(2);
  std::vector<Scalar> f(N + 1, Scalar(0)), g(N);
  for (std::size_t n = 1; n <= N; ++n) f[n] = m.k_t * S[n] - m.k_z * C[n] + mu * (half_diff * S2[n] - m.A_tz * C2[n]);
  for (std::size_t n = 0; n < N; ++n) g[n] = -(m.k_t * C[n] + m.k_z * S[n] + mu * (half_diff * C2[n] + m.A_tz * S2[n]));
  g[0] -= mu * half_sum;
  StopTail<Scalar> out;
  if (!(f[1] <= Scalar(0) && g[0] < Scalar(0))) return out;  // not a direction the slide settles on
  std::vector<std::array<Scalar, 3>> F(N);
  std::vector<Scalar> G(N);
  Vec3<Scalar> sumF = Vec3<Scalar>::Zero();
  Scalar sumG(0), power(1), previous(0), variation(0), g_variation(0), four_back(0);
  for (std::size_t n = 0; n < N; ++n) {
    const Scalar v[3] = {n == 0 ? Scalar(1) : Scalar(0), mu * C[n], mu * S[n]};
    const Scalar pivot = Scalar(static_cast<long long>(n)) * f[1] + g[0];
    for (int i = 0; i < 3; ++i) {
      Scalar r = -v[i];
      for (std::size_t j = 2; j <= n + 1; ++j) r -= Scalar(static_cast<long long>(n + 1 - j)) * f[j] * F[n + 1 - j][i];
      for (std::size_t j = 1; j <= n; ++j) r -= g[j] * F[n - j][i];
      F[n][i] = r / pivot;
    }
    Scalar r = -(K(0, 0) * F[n][0] + K(0, 1) * F[n][1] + K(0, 2) * F[n][2]);
    for (std::size_t j = 2; j <= n + 1; ++j) r -= Scalar(static_cast<long long>(n + 1 - j)) * f[j] * G[n + 1 - j];
    for (std::size_t j = 1; j <= n; ++j) r -= Scalar(2) * g[j] * G[n - j];
    const Scalar KnF = K(0, 0) * F[n][0] + K(0, 1) * F[n][1] + K(0, 2) * F[n][2];
    if (n) variation += abs(KnF) * abs(power), g_variation += abs(g[n]) * abs(power);
    G[n] = r / (Scalar(static_cast<long long>(n)) * f[1] + Scalar(2) * g[0]);
    const Vec3<Scalar> term = Vec3<Scalar>(F[n][0], F[n][1], F[n][2]) * power;
    const Scalar term_G = G[n] * power;
    sumF += term, sumG += term_G;
    const Scalar size = std::max(Scalar(term.cwiseAbs().maxCoeff()), Scalar(abs(term_G)));
    // At delta = 0 the first term is the whole value; a dual's derivative needs the second as well.
    if ((delta == Scalar(0) && n >= (is_dual_v<Scalar> ? 1u : 0u)) || (n >= 1 && std::max(size, previous) <= tolerance * std::max(Scalar(sumF.cwiseAbs().maxCoeff()), Scalar(abs(sumG))))) {
      out.F = sumF, out.G = sumG, out.last = delta == Scalar(0) ? Scalar(0) : std::max(size, previous), out.converged = true;
      out.KnF0 = K(0, 0) * F[0][0] + K(0, 1) * F[0][1] + K(0, 2) * F[0][2];
      // The sums' remainders past order n: F's terms fall (else not converged), at most halving, so
      // twice the last; g's coefficient m is at most B_m = (|k_t| + |k_z|)(|C_m| + |S_m|) + mu (|A_tt -
      // A_zz| / 2 + |A_tz|)(|C2_m| + |S2_m|) (cos and sin's coefficients, |c| + |s| >= 1), each the last
      // over m / (2 |delta|) or more, so the tail from m = n + 1 is at most 3 B_m |delta|^m where
      // 3 |delta| <= n + 2 (ratio <= 2/3), else not bounded: not taken as shrinking.
      const Scalar K_n = abs(K(0, 0)) + abs(K(0, 1)) + abs(K(0, 2));
      out.normal_variation = variation + Scalar(2) * K_n * std::max(size, previous);
      const std::size_t m1 = n + 1;
      const Scalar B = (abs(m.k_t) + abs(m.k_z)) * (abs(C[m1]) + abs(S[m1])) + mu * (abs(half_diff) + abs(m.A_tz)) * (abs(C2[m1]) + abs(S2[m1]));
      const bool bounded = Scalar(3) * abs(delta) <= Scalar(static_cast<long long>(n + 2));
      const Scalar g_tail = Scalar(3) * B * abs(Scalar(power * delta));
      out.shrinking = bounded && g_variation + g_tail < -g[0];
      F.resize(n + 1), G.resize(n + 1);
      out.F_n = std::move(F), out.G_n = std::move(G), out.f_n = std::move(f), out.g_n = std::move(g);
      return out;
    }
    if (n >= 4 && size > previous) return out;  // the terms grow: delta is past the series' reach
    // Falling at the rate of the last four terms, would they reach the tolerance by max_order?
    if (n == 4) four_back = size;
    if (n >= 8 && n % 4 == 0) {
      using std::log;
      const double rate = to_double(Scalar(log(size / four_back) / Scalar(4)));
      const double needed = to_double(Scalar(log(tolerance * std::max(Scalar(sumF.cwiseAbs().maxCoeff()), Scalar(abs(sumG))) / size)));
      if (!(rate < 0) || static_cast<double>(n) + needed / rate > static_cast<double>(max_order)) return out;
      four_back = size;
    }
    previous = size;
    power *= delta;
  }
  return out;
}

}  // namespace impact3d::stronge
