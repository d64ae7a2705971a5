// MPFR's correctly rounded sine and cosine, found faster: Arb encloses both (about 0.6 us at 100 digits,
// against 1.7 us for mpfr_sin_cos), and where each enclosure's ends round to the same MPFR number, that
// number is the correctly rounded value. Rounding to nearest is monotonic, so the true value, which lies
// between the ends, rounds there too. Where the ends round apart (a value near a tie, or an enclosure
// wider than usual, as Arb's cosine near pi/2) MPFR computes it. Whether the ends round alike is first
// read off the enclosure's limbs (round_ball, ball_rounding.hpp), at a fraction of the cost of rounding
// both ends through Arb and MPFR; what it declines (a midpoint on a tie, a round-up into the next binade,
// more limbs than the result) goes that way. At 100 digits it decided the sine and cosine of every one
// of 100 000 drawn angles; at 50 digits (168 bits) Arb's enclosure carries a limb more than the result's
// three, so it declines them all, and the ends are rounded as before.
#include "impact3d/scalar/multiprecision.hpp"

#include <arb.h>

#include "impact3d/scalar/ball_rounding.hpp"

namespace impact3d::mp {
namespace {

// Bits Arb carries beyond the result's: the enclosure is then some 2^-30 of a last place wide.
constexpr slong kGuardBits = 32;

// A thread's working numbers, kept from call to call so that a call at one precision seldom allocates.
// The results are rounded into sine and cosine here, and copied out only once both are decided, so
// that x may be the same number as s or c (as MPFR allows) when MPFR has to compute them after all.
struct ArbWork {
  arb_t x, s, c;
  arf_t lo, hi;
  mpfr_t sine, cosine, other;
  ArbWork() {
    arb_init(x), arb_init(s), arb_init(c);
    arf_init(lo), arf_init(hi);
    mpfr_inits2(MPFR_PREC_MIN, sine, cosine, other, static_cast<mpfr_ptr>(nullptr));
  }
  ~ArbWork() {
    arb_clear(x), arb_clear(s), arb_clear(c);
    arf_clear(lo), arf_clear(hi);
    mpfr_clears(sine, cosine, other, static_cast<mpfr_ptr>(nullptr));
  }
  ArbWork(const ArbWork&) = delete;
  ArbWork& operator=(const ArbWork&) = delete;
  void precision(mpfr_prec_t p) {
    if (mpfr_get_prec(other) == p) return;
    mpfr_set_prec(sine, p), mpfr_set_prec(cosine, p), mpfr_set_prec(other, p);
  }
};

// `out` (and `other`, of the same precision) the ends of `b` rounded to nearest; whether they agree.
bool rounded_once(mpfr_ptr out, mpfr_ptr other, const arb_t b, arf_t lo, arf_t hi, slong bits) {
  if (!arb_is_finite(b)) return false;
  arb_get_lbound_arf(lo, b, bits);
  arb_get_ubound_arf(hi, b, bits);
  arf_get_mpfr(out, lo, MPFR_RNDN);
  arf_get_mpfr(other, hi, MPFR_RNDN);
  return mpfr_equal_p(out, other) != 0;
}

}  // namespace

void sin_cos(mpfr_ptr s, mpfr_ptr c, mpfr_srcptr x) {
  // MPFR's alone: zero (whose sine keeps its sign), infinities and NaN, s and c of different
  // precisions, and magnitudes below 2^-1000. Above that every end Arb hands over lies far inside
  // MPFR's exponent range (impact3d keeps the default, reaching 2^(1-2^30)), so none underflows.
  const mpfr_prec_t p = mpfr_get_prec(s);
  if (mpfr_regular_p(x) && mpfr_get_exp(x) > -1000 && mpfr_get_prec(c) == p) {
    thread_local ArbWork w;
    w.precision(p);
    arf_set_mpfr(arb_midref(w.x), x);
    mag_zero(arb_radref(w.x));
    const slong bits = static_cast<slong>(p) + kGuardBits;
    arb_sin_cos(w.s, w.c, w.x, bits);
    // Mostly decided from the enclosures' limbs (ball_rounding.hpp); else by rounding their ends.
    if ((round_ball(w.sine, w.s) && round_ball(w.cosine, w.c)) ||
        (rounded_once(w.sine, w.other, w.s, w.lo, w.hi, bits) && rounded_once(w.cosine, w.other, w.c, w.lo, w.hi, bits))) {
      mpfr_set(s, w.sine, MPFR_RNDN);  // exact: the same precision
      mpfr_set(c, w.cosine, MPFR_RNDN);
      return;
    }
  }
  mpfr_sin_cos(s, c, x, MPFR_RNDN);
}

}  // namespace impact3d::mp
