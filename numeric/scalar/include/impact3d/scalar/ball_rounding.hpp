// Whether every number of an Arb ball rounds to nearest to one and the same MPFR number, read off the
// midpoint's limbs and the radius as integers. The sines and cosines at 100 digits are taken this way
// (mpfr_sin_cos.cpp): rounding both ends of each enclosure through Arb and MPFR took a third as many
// instructions as Arb's sine and cosine themselves (BENCHMARKS.md).
//
// Rounding to nearest is monotonic, so the ball [m - r, m + r] rounds to one number R = RN(m) when
// both ends lie strictly inside R's interval, above R - (the gap below R) / 2 and below R + (the gap
// above R) / 2 (an end on a boundary may round either way). In units of m's lowest limb bit, with `low`
// the bits of m below R's last place and h half a last place:
// - m rounded down (low < h): the end above is h - low away; the one below low + h, or low + h / 2
//   where R is a power of two (the numbers below it lie half as far apart);
// - m rounded up (low > h): R - m is 2h - low, so the end above is 3h - low away and the one below
//   low - h (the number below R is m truncated, in R's binade).
// The ball is decided where r < the nearer distance. Declined, for the caller's general route: a tie
// (low = h), a round-up carrying into the next binade, a midpoint of more limbs than the result, a
// special midpoint or an infinite radius, exponents beyond 2^40 in magnitude (the unit arithmetic below
// then cannot overflow) or outside MPFR's current range, precisions beyond eight limbs, and precisions
// that leave fewer than two of their limbs' bits unused (383 bits, say). Declining is never wrong, only
// slower.
#pragma once

#include <arb.h>
#include <mpfr.h>

#include <cstdint>

namespace impact3d::mp {

// `out` (its precision p kept) set to the number every point of b rounds to, when there is one and it
// is decided here; false (out untouched) otherwise.
inline bool round_ball(mpfr_ptr out, const arb_t b) {
  using Limb = mp_limb_t;
  constexpr int kMaxLimbs = 8;
  const arf_struct* mid = arb_midref(b);
  const mag_struct* rad = arb_radref(b);
  constexpr slong kExponentBound = slong{1} << 40;
  const mpfr_prec_t p = mpfr_get_prec(out);
  if (p > 64 * kMaxLimbs || arf_is_special(mid) || !mag_is_finite(rad) || COEFF_IS_MPZ(ARF_EXP(mid)) ||
      COEFF_IS_MPZ(MAG_EXP(rad)))
    return false;
  const slong e = ARF_EXP(mid), rad_exp = MAG_EXP(rad);
  if (e < -kExponentBound || e > kExponentBound || rad_exp < -kExponentBound || rad_exp > kExponentBound ||
      e < mpfr_get_emin() || e > mpfr_get_emax())
    return false;
  const int n = static_cast<int>((p + 63) / 64), spare = 64 * n - static_cast<int>(p);
  if (spare < 2) return false;
  const Limb* xp;
  mp_size_t xn;
  ARF_GET_MPN_READONLY(xp, xn, mid);
  if (xn > n) return false;
  Limb m[kMaxLimbs] = {};  // m's limbs at the top of n, the value 0.m x 2^e as MPFR's
  for (mp_size_t i = 0; i < xn; ++i) m[n - xn + i] = xp[i];

  const Limb h = Limb{1} << (spare - 1), low = m[0] & ((h << 1) - 1);
  if (low == h) return false;
  const bool up = low > h;
  Limb distance;
  m[0] -= low;  // R's limbs, before a round-up
  if (up) {
    if (mpn_add_1(m, m, n, h << 1) != 0) return false;  // into the next binade
    distance = low - h;  // the end below; the one above, 3h - low, is further
  } else {
    bool power_of_two = m[n - 1] == Limb{1} << 63;
    for (int i = 0; i < n - 1; ++i) power_of_two = power_of_two && m[i] == 0;
    const Limb below = power_of_two ? low + h / 2 : low + h;
    distance = h - low < below ? h - low : below;
  }

  // r = man x 2^(exp - MAG_BITS); in units of 2^(e - 64 n): man x 2^shift.
  const Limb man = MAG_MAN(rad);
  if (man != 0) {
    const slong shift = rad_exp - MAG_BITS - e + 64 * n;
    if (shift >= 0) {
      if (shift > 63 - MAG_BITS || (man << shift) >= distance) return false;
    } else if (shift > -64) {
      // man x 2^shift < distance, as man < distance x 2^-shift, exactly.
      const unsigned __int128 scaled = static_cast<unsigned __int128>(distance) << -shift;
      if (man >= scaled) return false;
    }  // else r < 2^30 x 2^-64 units: below any distance, which is at least 1
  }

  Limb* d = static_cast<Limb*>(mpfr_custom_get_significand(out));
  for (int i = 0; i < n; ++i) d[i] = m[i];
  mpfr_custom_init_set(out, ARF_SGNBIT(mid) ? -MPFR_REGULAR_KIND : MPFR_REGULAR_KIND, static_cast<mpfr_exp_t>(e), p, d);
  return true;
}

}  // namespace impact3d::mp
