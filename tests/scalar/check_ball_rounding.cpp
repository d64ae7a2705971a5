// round_ball (scalar/ball_rounding.hpp), which decides from an Arb ball's limbs whether all of it
// rounds to one MPFR number, against the ball's ends computed exactly in MPFR at 4000 bits and rounded to
// nearest: wherever round_ball decides, both ends round to the number it gives. The balls are drawn at
// the edges its reasoning turns on: a midpoint at, beside and far from a tie, at the top and bottom of its
// last place, with all its kept bits ones (the round-up carries into the next binade) or a power of two
// (the numbers below lie closer), with fewer limbs than the result; radii of none, of 30-bit mantissas
// times powers of two from 2^-70 units of the midpoint's last limb bit to 2^20 last places (past 2^63
// units where the last place is 2^44 units or more: the decline of radii too large to shift), and of each
// distance to an end of the rounding interval, a unit or half a unit either side (exactly so where that
// fits a radius's 30 bits; else rounded up or down to them). check_rotation
// holds the sines and cosines that use it to Boost's (MPFR's) bit for bit.
#include <catch2/catch.hpp>

#include <random>

#include "impact3d/scalar/ball_rounding.hpp"

namespace check_ball_rounding {

using impact3d::mp::round_ball;

namespace {

struct Numbers {
  mpfr_t out, lo, hi, mid, rad;
  explicit Numbers(mpfr_prec_t p) {
    mpfr_init2(out, p);
    mpfr_inits2(4000, lo, hi, mid, rad, static_cast<mpfr_ptr>(nullptr));
  }
  ~Numbers() { mpfr_clears(out, lo, hi, mid, rad, static_cast<mpfr_ptr>(nullptr)); }
  Numbers(const Numbers&) = delete;
  Numbers& operator=(const Numbers&) = delete;
};

struct Ball {
  arb_t x;
  Ball() { arb_init(x); }
  ~Ball() { arb_clear(x); }
  Ball(const Ball&) = delete;
  Ball& operator=(const Ball&) = delete;
};

// b's radius set to r units of 2^unit (r below 2^30: exact).
void set_radius(Ball& b, unsigned long r, long unit) {
  mag_set_ui(arb_radref(b.x), r);
  mag_mul_2exp_si(arb_radref(b.x), arb_radref(b.x), unit);
}

// The ball with midpoint 0.m x 2^e (n limbs, the sign `negative`) and radius man x 2^(rexp - 30).
void set_ball(Ball& b, const mp_limb_t* m, int n, long e, bool negative, unsigned long man, long rexp) {
  mpfr_t view;  // m's limbs read in place, never freed
  mpfr_custom_init_set(view, negative ? -MPFR_REGULAR_KIND : MPFR_REGULAR_KIND, e, 64 * n, const_cast<mp_limb_t*>(m));
  arf_set_mpfr(arb_midref(b.x), view);
  if (man == 0) mag_zero(arb_radref(b.x));
  else mag_set_ui_2exp_si(arb_radref(b.x), man, rexp - 30);
}

// Whether both ends of b round to one number of out's precision, and which (in num.out's place).
bool ends_round_alike(Numbers& num, const Ball& b, mpfr_ptr rounded) {
  arf_get_mpfr(num.mid, arb_midref(b.x), MPFR_RNDN);  // exact: 4000 bits hold it
  arf_t r;
  arf_init(r);
  arf_set_mag(r, arb_radref(b.x));
  arf_get_mpfr(num.rad, r, MPFR_RNDN);
  arf_clear(r);
  mpfr_sub(num.lo, num.mid, num.rad, MPFR_RNDN);  // exact: the radius lies within 4000 bits of the midpoint
  mpfr_add(num.hi, num.mid, num.rad, MPFR_RNDN);
  mpfr_t other;
  mpfr_init2(other, mpfr_get_prec(rounded));
  mpfr_set(rounded, num.lo, MPFR_RNDN);
  mpfr_set(other, num.hi, MPFR_RNDN);
  const bool alike = mpfr_equal_p(rounded, other) != 0 && mpfr_signbit(rounded) == mpfr_signbit(other);
  mpfr_clear(other);
  return alike;
}

}  // namespace

TEST_CASE("round_ball decides only balls whose ends round to one number, and gives it", "[ball_rounding]") {
  std::mt19937_64 g(20261127);
  int checked = 0, decided = 0, wrong = 0;
  constexpr int kBalls = 40000;
  // 100 digits (334 bits), 50 digits (168), quad (113), a whole number of limbs less one bit (383: no
  // room for the round bit and one below, so always declined), and 200.
  for (const mpfr_prec_t p : {334, 168, 113, 200, 383}) {
    const int n = static_cast<int>((p + 63) / 64), spare = 64 * n - static_cast<int>(p);
    Numbers num(p);
    mpfr_t expected;
    mpfr_init2(expected, p);
    Ball b;
    int decided_here = 0;
    for (int k = 0; k < kBalls; ++k) {
      mp_limb_t m[8];
      for (int i = 0; i < n; ++i) m[i] = g();
      if (g() % 4 == 0)
        for (int i = 0; i < n; ++i) m[i] = ~mp_limb_t{0};
      if (g() % 4 == 0) {
        for (int i = 0; i < n - 1; ++i) m[i] = 0;
        m[n - 1] = mp_limb_t{1} << 63;
      }
      const mp_limb_t h = mp_limb_t{1} << (spare - 1);
      mp_limb_t low;
      switch (g() % 6) {
        case 0: low = h; break;                           // a tie
        case 1: low = h - 1 - g() % 3; break;             // just below
        case 2: low = h + 1 + g() % 3; break;             // just above
        case 3: low = g() % 4; break;                     // on or just above a number
        case 4: low = (h << 1) - 1 - g() % 3; break;      // just below the next number
        default: low = g() & ((h << 1) - 1);
      }
      low &= (h << 1) - 1;  // within the bits below the last place (at 383 bits, h = 1)
      m[0] = (m[0] & ~((h << 1) - 1)) | low;
      m[n - 1] |= mp_limb_t{1} << 63;
      if (g() % 4 == 0) {  // a midpoint of fewer limbs: its low bits zero
        const int zero_limbs = static_cast<int>(g() % static_cast<unsigned>(n));
        for (int i = 0; i < zero_limbs; ++i) m[i] = 0;
        low = m[0] & ((h << 1) - 1);
      }
      const long e = static_cast<long>(g() % 41) - 20, unit = e - 64 * n;
      set_ball(b, m, n, e, (g() & 1) != 0, 0, 0);
      mag_struct* rad = arb_radref(b.x);
      switch (g() % 4) {
        case 0: break;  // none
        case 1:         // man x 2^(j - 30) units, 1 <= man <= 2^30, j from -40 to spare + 20
        {
          const long j = unit - 70 + static_cast<long>(g() % static_cast<unsigned>(spare + 61));  // the last first
          mag_set_ui_2exp_si(rad, 1 + g() % (1ul << 30), j);
        }
          break;
        default: {  // a distance to an end of the interval, or a unit or half a unit either side
          const mp_limb_t distances[] = {h > low ? h - low : low - h, low + h, low + h / 2, 3 * h - low};
          const bool halves = g() % 2 != 0;
          const mp_limb_t d = distances[g() % 4] << (halves ? 1 : 0);
          mp_limb_t r = d == 0 ? 1 : d + g() % 3 - 1;  // in halves: d - 1/2, d, d + 1/2
          if (r == 0) r = 1;
          if (g() % 2) mag_set_ui(rad, r);
          else mag_set_ui_lower(rad, r);
          mag_mul_2exp_si(rad, rad, halves ? unit - 1 : unit);
        }
      }
      const bool alike = ends_round_alike(num, b, expected);
      mpfr_set_ui(num.out, 7, MPFR_RNDN);
      if (round_ball(num.out, b.x)) {
        ++decided_here;
        if (!alike || !mpfr_equal_p(num.out, expected) || mpfr_signbit(num.out) != mpfr_signbit(expected)) {
          ++wrong;
          UNSCOPED_INFO("precision " << p << ", ball " << k);
        }
      }
      ++checked;
    }
    mpfr_clear(expected);
    if (spare < 2) CHECK(decided_here == 0);
    else CHECK(decided_here > kBalls / 4);  // the path is taken, not only declined
    decided += decided_here;
  }
  CHECK(wrong == 0);
  CHECK(checked == 5 * kBalls);
  CHECK(decided > 0);
}

// Named edges, worked by hand at 113 bits (two limbs, 15 spare bits, half a last place h = 2^14 units of
// the lowest limb bit).
TEST_CASE("round_ball at a power of two and at a tie", "[ball_rounding]") {
  constexpr mpfr_prec_t p = 113;
  Numbers num(p);
  Ball b;
  mpfr_t expected;
  mpfr_init2(expected, p);
  const long e = 0, unit = e - 128;  // 0.1 (binary) x 2^0: the midpoints below are near 1/2
  const mp_limb_t h = mp_limb_t{1} << 14;
  // Midpoint 1/2 exactly (a power of two), radius 0.4 h: the end below, 1/2 - 0.4 h, lies above the
  // boundary 1/2 - h/2 with the number below (the numbers below 1/2 are h apart, not 2h): decided, 1/2.
  const mp_limb_t half[2] = {0, mp_limb_t{1} << 63};
  set_ball(b, half, 2, e, false, 429496730, unit + 14);  // just above 0.4 x 2^30, times 2^(14 - 30) units
  CHECK(ends_round_alike(num, b, expected));
  REQUIRE(round_ball(num.out, b.x));
  CHECK(mpfr_equal_p(num.out, expected));
  CHECK(mpfr_cmp_d(num.out, 0.5) == 0);
  // Radius 0.6 h: the end below passes that boundary and rounds to the number below 1/2; declined.
  set_ball(b, half, 2, e, false, 644245095, unit + 14);  // 0.6 x 2^30
  CHECK_FALSE(ends_round_alike(num, b, expected));
  CHECK_FALSE(round_ball(num.out, b.x));
  // 1/2 and 2^11 units above it (R a power of two, low not zero): the end below is low + h/2 = 10240
  // units away (not low + h: the numbers below 1/2 are h apart), the end above h - low = 14336. Radius
  // 10000: decided; 10400: the end below crosses, the end above does not; declined.
  const mp_limb_t above_half[2] = {mp_limb_t{1} << 11, mp_limb_t{1} << 63};
  set_ball(b, above_half, 2, e, false, 0, 0);
  set_radius(b, 10000, unit);
  CHECK(ends_round_alike(num, b, expected));
  REQUIRE(round_ball(num.out, b.x));
  CHECK(mpfr_equal_p(num.out, expected));
  set_radius(b, 10400, unit);
  CHECK_FALSE(ends_round_alike(num, b, expected));
  CHECK_FALSE(round_ball(num.out, b.x));
  // An infinite radius: declined, however far the midpoint lies from a tie.
  mag_inf(arb_radref(b.x));
  CHECK_FALSE(round_ball(num.out, b.x));
  // A tie with no radius: declined (MPFR's ties-to-even is left to the general route).
  const mp_limb_t tie[2] = {h, mp_limb_t{1} << 63};
  set_ball(b, tie, 2, e, false, 0, 0);
  CHECK_FALSE(round_ball(num.out, b.x));
  // One unit below the tie, no radius: rounds down, decided.
  const mp_limb_t below_tie[2] = {h - 1, mp_limb_t{1} << 63};
  set_ball(b, below_tie, 2, e, true, 0, 0);
  CHECK(ends_round_alike(num, b, expected));
  REQUIRE(round_ball(num.out, b.x));
  CHECK(mpfr_equal_p(num.out, expected));
  CHECK(mpfr_signbit(num.out) != 0);
  // R odd (its last place, bit 15, set), 256 units above it, radius exactly h - 256: the end above lands
  // on the tie between R and the number above, which rounds to even, away from R; declined.
  const mp_limb_t odd[2] = {(mp_limb_t{1} << 15) | 256, mp_limb_t{1} << 63};
  set_ball(b, odd, 2, e, false, (16384 - 256) << 16, unit + 14);  // (h - 256) x 2^16 x 2^(14 - 30) units
  CHECK_FALSE(ends_round_alike(num, b, expected));
  CHECK_FALSE(round_ball(num.out, b.x));
  // One unit less of radius: both ends round to R; decided.
  set_ball(b, odd, 2, e, false, (16384 - 257) << 16, unit + 14);
  CHECK(ends_round_alike(num, b, expected));
  REQUIRE(round_ball(num.out, b.x));
  CHECK(mpfr_equal_p(num.out, expected));
  mpfr_clear(expected);
}

// The same tie at 334 bits (six limbs, 50 spare bits, h = 2^49 units), where the distance, 2^40 units,
// is a radius of at least one unit: R odd (bit 50 set), 2^49 - 2^40 units above it, radius 2^40 units.
TEST_CASE("round_ball at a tie a radius of many units away", "[ball_rounding]") {
  constexpr mpfr_prec_t p = 334;
  Numbers num(p);
  Ball b;
  mpfr_t expected;
  mpfr_init2(expected, p);
  const long e = 0, unit = e - 384;
  mp_limb_t m[6] = {(mp_limb_t{1} << 50) | ((mp_limb_t{1} << 49) - (mp_limb_t{1} << 40)), 0, 0, 0, 0, mp_limb_t{1} << 63};
  set_ball(b, m, 6, e, false, 1ul << 29, unit + 41);  // 2^29 x 2^(41 - 30) = 2^40 units
  CHECK_FALSE(ends_round_alike(num, b, expected));
  CHECK_FALSE(round_ball(num.out, b.x));
  set_ball(b, m, 6, e, false, (1ul << 30) - 1, unit + 40);  // just below 2^40 units
  CHECK(ends_round_alike(num, b, expected));
  REQUIRE(round_ball(num.out, b.x));
  CHECK(mpfr_equal_p(num.out, expected));
  mpfr_clear(expected);
}

}  // namespace check_ball_rounding
