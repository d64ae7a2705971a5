// FixedFloat's own +, -, x and quotient by an integer against MPFR's calls at the same precision, bit for bit: sign, kind,
// exponent and every limb; its other functions against Boost's MPFR numbers (float100), which it stands
// in for on the lean route; and that route's scene from raw parameters against the same computed in
// Boost's numbers. (check_lean holds the lean solve at 100 digits, computed in FixedFloat, to analyze's
// in Boost's numbers bit for bit.) The operands are drawn to reach each path of the rounding: exponents apart by
// 0 to P + 3 places (full overlap, partial, and y wholly below x's round bit), near-equal magnitudes
// (cancellation to few bits), significands with long runs of ones (carries through every limb, rounding up
// to the next power of two), exact ties (a last bit beside a half), signed zeros, infinities, NaNs, and
// exponents beyond the fast range (MPFR's own call must then be taken).
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <random>
#include <vector>

#include "impact3d/scalar/fixed_float.hpp"
#include "impact3d/scalar/limb_product.hpp"
#include "impact3d/mechanics/lean.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "impact3d/mechanics/raw_collision.hpp"
#include "support.hpp"

namespace check_fixed_float {

using F = impact3d::mp::FixedFloat<334>;

namespace {

constexpr int kP = 334;

// An MPFR number of precision kP.
struct Mpfr {
  mpfr_t x;
  Mpfr() { mpfr_init2(x, kP); }
  ~Mpfr() { mpfr_clear(x); }
  Mpfr(const Mpfr&) = delete;
  Mpfr& operator=(const Mpfr&) = delete;
};

// Whether f is exactly MPFR's x: the same kind, sign (NaN's aside) and bits.
bool same(const F& f, mpfr_srcptr x) {
  if (mpfr_nan_p(x)) return f.kind() == F::kNaN;
  if (f.kind() == F::kNaN) return false;
  if ((mpfr_signbit(x) != 0) != f.negative()) return false;
  if (mpfr_inf_p(x)) return f.kind() == F::kInf;
  if (mpfr_zero_p(x)) return f.kind() == F::kZero;
  if (f.limbs()[0] & ((F::Limb{1} << F::kSpare) - 1)) return false;  // bits below the last place
  if (!(f.limbs()[F::kLimbs - 1] >> 63)) return false;                // normalized
  Mpfr back;
  f.to(back.x);
  return f.kind() == F::kRegular && mpfr_equal_p(back.x, x) && mpfr_get_exp(back.x) == mpfr_get_exp(x);
}

// Significands drawn to reach carries, ties and cancellations.
struct Draw {
  std::mt19937_64 g{20261127};
  void significand(mpfr_ptr x) {
    mpz_t z;
    mpz_init(z);
    switch (g() % 5) {
      case 0:  // uniform
        for (int i = 0; i < 6; ++i) mpz_mul_2exp(z, z, 64), mpz_add_ui(z, z, g());
        break;
      case 1:  // all ones but a few of the last bits
        mpz_set_ui(z, 1), mpz_mul_2exp(z, z, kP), mpz_sub_ui(z, z, 1 + g() % 8);
        break;
      case 2:  // a power of two, or one place above it
        mpz_set_ui(z, 1), mpz_mul_2exp(z, z, kP - 1), mpz_add_ui(z, z, g() % 2);
        break;
      case 3:  // few bits set: products and sums that are exact or lie on a tie
        mpz_set_ui(z, 1), mpz_mul_2exp(z, z, kP - 1);
        for (int k = 0, n = 1 + g() % 4; k < n; ++k) mpz_setbit(z, g() % kP);
        break;
      default:  // uniform in the high bits, zeros below
        mpz_set_ui(z, g() | (1ULL << 63)), mpz_mul_2exp(z, z, kP - 64);
        break;
    }
    mpz_setbit(z, kP - 1);
    mpfr_set_z_2exp(x, z, -kP, MPFR_RNDN);  // in [1/2, 1), exact (kP bits)
    mpz_clear(z);
    if (g() % 2) mpfr_neg(x, x, MPFR_RNDN);
  }
  // x with exponent e; sometimes y close to x (cancellation).
  void pair(mpfr_ptr x, mpfr_ptr y) {
    significand(x);
    mpfr_mul_2si(x, x, static_cast<long>(g() % 41) - 20, MPFR_RNDN);
    const int how = static_cast<int>(g() % 4);
    if (how == 0) {  // x +- a few places
      mpfr_set(y, x, MPFR_RNDN);
      for (int k = 0, n = 1 + g() % 3; k < n; ++k) g() % 2 ? mpfr_nextabove(y) : mpfr_nextbelow(y);
      if (g() % 2) mpfr_neg(y, y, MPFR_RNDN);
    } else {
      significand(y);
      const long d = how == 1 ? static_cast<long>(g() % (kP + 4)) : static_cast<long>(g() % 70) - 35;
      mpfr_mul_2si(y, y, mpfr_get_exp(x) - d, MPFR_RNDN);
    }
  }
};

template <typename Op, typename Ref>
int agree(const F& a, const F& b, mpfr_srcptr ma, mpfr_srcptr mb, Op op, Ref ref) {
  Mpfr want;
  ref(want.x, ma, mb, MPFR_RNDN);
  const F got = op(a, b);
  INFO("a = " << mpfr_get_d(ma, MPFR_RNDN) << ", b = " << mpfr_get_d(mb, MPFR_RNDN));
  REQUIRE(same(got, want.x));
  return 1;
}

int agree_all(mpfr_srcptr ma, mpfr_srcptr mb) {
  const F a = F::of(ma), b = F::of(mb);
  REQUIRE(same(a, ma));
  REQUIRE(same(b, mb));
  int n = 0;
  n += agree(a, b, ma, mb, [](const F& x, const F& y) { return x + y; }, mpfr_add);
  n += agree(a, b, ma, mb, [](const F& x, const F& y) { return x - y; }, mpfr_sub);
  n += agree(a, b, ma, mb, [](const F& x, const F& y) { return x * y; }, mpfr_mul);
  n += agree(a, b, ma, mb, [](const F& x, const F& y) { return x / y; }, mpfr_div);
  // Comparisons as MPFR's (NaN unordered).
  CHECK((a < b) == (mpfr_less_p(ma, mb) != 0));
  CHECK((a <= b) == (mpfr_lessequal_p(ma, mb) != 0));
  CHECK((a == b) == (mpfr_equal_p(ma, mb) != 0));
  CHECK((a >= b) == (mpfr_greaterequal_p(ma, mb) != 0));
  CHECK((a > b) == (mpfr_greater_p(ma, mb) != 0));
  return n;
}

}  // namespace

TEST_CASE("FixedFloat's +, -, x and / are MPFR's, bit for bit, on drawn operands", "[fixed_float]") {
  REQUIRE(mpfr_get_emax() == MPFR_EMAX_DEFAULT);  // the fast range assumes MPFR's default exponents
  Draw d;
  Mpfr x, y;
  int checked = 0;
  constexpr int kPairs = 200000;
  for (int k = 0; k < kPairs; ++k) {
    d.pair(x.x, y.x);
    checked += agree_all(x.x, y.x);
  }
  CHECK(checked == 4 * kPairs);
}

TEST_CASE("FixedFloat's special values and the edges of the fast range are MPFR's", "[fixed_float]") {
  std::vector<Mpfr> values(14);
  mpfr_set_zero(values[0].x, 1), mpfr_set_zero(values[1].x, -1);
  mpfr_set_inf(values[2].x, 1), mpfr_set_inf(values[3].x, -1), mpfr_set_nan(values[4].x);
  mpfr_set_ui(values[5].x, 1, MPFR_RNDN), mpfr_set_si(values[6].x, -3, MPFR_RNDN);
  // Beyond the fast range, at and beyond MPFR's: products overflow and underflow as MPFR's do.
  mpfr_set_ui_2exp(values[7].x, 3, (1L << 28) - 2, MPFR_RNDN);
  mpfr_set_ui_2exp(values[8].x, 5, -(1L << 28), MPFR_RNDN);
  mpfr_set_ui_2exp(values[9].x, 1, mpfr_get_emax() - 1, MPFR_RNDN);
  mpfr_set_ui_2exp(values[10].x, 1, mpfr_get_emin(), MPFR_RNDN);
  mpfr_set_si_2exp(values[11].x, -7, (1L << 29), MPFR_RNDN);
  // The largest significand: its successor is the next power of two.
  mpfr_set_inf(values[12].x, 1), mpfr_nextbelow(values[12].x), mpfr_div_2ui(values[12].x, values[12].x, 1L << 29, MPFR_RNDN);
  mpfr_set_d(values[13].x, 0.1, MPFR_RNDN);
  int checked = 0;
  for (const auto& a : values)
    for (const auto& b : values) checked += agree_all(a.x, b.x);
  CHECK(checked == 4 * 14 * 14);
}

// The product's assembly (limb_product.hpp, taken wherever the processor has mulx and adx) against GMP's
// mpn_mul_n, limb for limb, on limbs drawn from patterns that reach its carries: all ones (every column
// carries in both chains), zero, one, the top bit alone, all but the top bit, and uniform limbs; and on
// squares, which FixedFloat also takes through it. Exact integers: any difference is an error. The top
// product (multiply6_high) is held to its bound below the whole on the same operands.
TEST_CASE("limb_product's assembly is GMP's product, limb for limb", "[fixed_float]") {
  namespace lp = impact3d::mp::limb_product;
  if (!lp::kAvailable) {
    WARN("this processor lacks mulx or adx, or IMPACT3D_GMP_PRODUCT is set: FixedFloat takes GMP's "
         "product, and the assembly is not run");
    return;
  }
  using Limb = lp::Limb;
  std::mt19937_64 g(20261128);
  const Limb patterns[] = {~Limb{0}, 0, 1, Limb{1} << 63, ~Limb{0} >> 1};
  auto limb = [&] { const auto k = g() % 7; return k < 5 ? patterns[k] : g(); };
  // The top product (21 of the 36 limb products) within its stated bound below the whole:
  // 0 <= a * b - T < 5 * 2^384, T its limbs 5 .. 11 times 2^320.
  Limb last_gap = 0;
  auto top_within = [&](const Limb* a, const Limb* b) {
    Limb whole[12], top[7], t[12] = {}, gap[12];
    mpn_mul_n(whole, a, b, 6);
    lp::multiply6_high(top, a, b);
    for (int i = 0; i < 7; ++i) t[5 + i] = top[i];
    bool within = mpn_sub_n(gap, whole, t, 12) == 0 && gap[6] < 5;
    for (int i = 7; i < 12; ++i) within = within && gap[i] == 0;
    if (!within) FAIL_CHECK("the top product of " << a[0] << ", ... is not within 5 * 2^384 below the whole");
    last_gap = gap[6];
    return static_cast<int>(within);
  };
  int checked = 0, top_checked = 0;
  constexpr int kPairs = 100000;
  for (int k = 0; k < kPairs; ++k) {
    Limb a[6], b[6], mine[12], gmp[12];
    for (int i = 0; i < 6; ++i) a[i] = limb(), b[i] = limb();
    for (const Limb* rhs : {static_cast<const Limb*>(b), static_cast<const Limb*>(a)}) {
      lp::multiply6(mine, a, rhs);
      mpn_mul_n(gmp, a, rhs, 6);
      bool same_limbs = true;
      for (int i = 0; i < 12; ++i) same_limbs = same_limbs && mine[i] == gmp[i];
      if (!same_limbs) FAIL_CHECK("the products of " << a[0] << ", ... differ");
      checked += same_limbs;
      top_checked += top_within(a, rhs);
    }
  }
  CHECK(checked == 2 * kPairs);
  CHECK(top_checked == 2 * kPairs);
  // All-ones limbs leave out the most: 4.99... * 2^384, so the bound is nearly reached there.
  Limb ones[6];
  std::fill(ones, ones + 6, ~Limb{0});
  CHECK(top_within(ones, ones) == 1);
  CHECK(last_gap == 4);
}

// top_decides against the rounding it stands for: wherever it says the top decides, every value the
// whole product or quotient can take, [x, x + 13) units of x's lowest bit (limb_product.hpp's bound
// and the reciprocal's, doubled by the normalizing shift, and T's bits under x), rounds to nearest as x
// does, and none is a tie. Checked in half units at every x within 20 of the tie, of the top and of
// zero, and at drawn x; and it must decide x = 0 (an exact product of short operands) and almost every
// drawn x, else the fast path is idle.
TEST_CASE("A product's top decides its rounding only where the rest cannot change it", "[fixed_float]") {
  using Limb = F::Limb;
  constexpr Limb half = Limb{1} << (F::kSpare - 1), top = 2 * half;
  // The kept part's change from rounding y half units: 0 down, 1 up, -1 a tie.
  auto rounding = [&](Limb y) -> int {
    if (y >= 2 * top) return 1;  // carried into the last place, then rounded down: the same as up from below
    return y < 2 * half ? 0 : y > 2 * half ? 1 : -1;
  };
  std::vector<Limb> xs;
  for (Limb k = 0; k <= 40; ++k) xs.insert(xs.end(), {half - 20 + k, top - 1 - k / 2, k / 2});
  std::mt19937_64 g(20261127);
  int decided_drawn = 0;
  constexpr int kDrawn = 100000;
  for (int k = 0; k < kDrawn; ++k) {
    xs.push_back(g() % top);
    decided_drawn += F::top_decides(xs.back());
  }
  int checked = 0;
  for (const Limb x : xs) {
    if (!F::top_decides(x)) continue;
    bool same = rounding(2 * x) != -1;
    for (Limb h = 1; h < 26; ++h) same = same && rounding(2 * x + h) == rounding(2 * x);
    if (!same) FAIL_CHECK("top_decides(" << x << ") though the rest can change its rounding");
    checked += same;
  }
  CHECK(F::top_decides(0));
  CHECK(decided_drawn >= kDrawn - 1);
  CHECK(checked > kDrawn);
}

// Products built on and about a tie, where the top (multiply6_high) cannot decide the rounding and the
// whole product is taken: random operands land there about once in 2^45, so the test above never sees
// that path run. The product's last place is bit P - 1 of the 2P-bit integer A B or, where A B has all
// 2P bits, bit P ("wide"); its round bit just below. An exact tie: A = 2^s A', B = 2^(r - s) B' with
// A', B' drawn and odd, r the round bit, so that A B = 2^r A' B' with A' B' odd (the last place's parity
// drawn with them, for ties to even). About a tie: A drawn and odd, B solving A B = the tie less d
// modulo 2^(r + 1), d from 2 units of x's lowest bit above the tie to 20 below, plus drawn bits under a
// unit. Each product against mpfr_mul, bit for bit; at least a third of them must leave the top
// undecided (where the assembly runs), and there must be exact ties of both widths.
TEST_CASE("Products on and about a tie, which the top cannot decide, are MPFR's", "[fixed_float]") {
  namespace lp = impact3d::mp::limb_product;
  std::mt19937_64 g(20261129);
  mpz_t A, B, target, t, mod, prod;
  for (mpz_ptr z : {A, B, target, t, mod, prod}) mpz_init(z);
  auto drawn = [&](mpz_ptr z, unsigned bits) {  // uniform below 2^bits
    mpz_set_ui(z, 0);
    for (unsigned i = 0; i < bits; i += 64) mpz_mul_2exp(z, z, 64), mpz_add_ui(z, z, g());
    mpz_fdiv_r_2exp(z, z, bits);
  };
  auto drawn_odd = [&](mpz_ptr z, unsigned bits) {  // exactly `bits` bits, odd
    drawn(z, bits);
    mpz_setbit(z, bits - 1), mpz_setbit(z, 0);
  };
  int built = 0, checked = 0, top_undecided = 0, ties[2] = {0, 0};
  constexpr int kTries = 4000;
  for (int k = 0; k < kTries; ++k) {
    const unsigned wide = g() % 2, round_bit = kP - 2 + wide, unit = round_bit - (F::kSpare - 1);
    const long units = g() % 4 == 0 ? 0 : static_cast<long>(g() % 23) - 2;
    const bool exact = units == 0 && g() % 2 == 0;
    if (exact) {
      const unsigned s = 60 + static_cast<unsigned>(g() % (round_bit - 119));
      drawn_odd(A, kP - s), mpz_mul_2exp(A, A, s);
      drawn_odd(B, kP - (round_bit - s)), mpz_mul_2exp(B, B, round_bit - s);
    } else {
      drawn_odd(A, kP);
      mpz_set_ui(target, 0), mpz_setbit(target, round_bit);
      mpz_set_si(t, units), mpz_mul_2exp(t, t, unit), mpz_sub(target, target, t);
      drawn(t, unit), mpz_sub(target, target, t);
      mpz_set_ui(mod, 0), mpz_setbit(mod, round_bit + 1);
      REQUIRE(mpz_invert(t, A, mod) != 0);
      mpz_mul(B, target, t), mpz_mod(B, B, mod);
      if (!wide) mpz_setbit(B, kP - 1);  // B's top bit is free modulo 2^(P - 1)
    }
    mpz_mul(prod, A, B);
    if (mpz_sizeinbase(A, 2) != kP || mpz_sizeinbase(B, 2) != kP || mpz_sizeinbase(prod, 2) != 2 * kP - 1 + wide) continue;
    ++built;
    Mpfr ma, mb;
    mpfr_set_z_2exp(ma.x, A, -kP, MPFR_RNDN), mpfr_set_z_2exp(mb.x, B, -kP, MPFR_RNDN);
    if (g() % 2) mpfr_neg(ma.x, ma.x, MPFR_RNDN);
    const F a = F::of(ma.x), b = F::of(mb.x);
    checked += agree(a, b, ma.x, mb.x, [](const F& x, const F& y) { return x * y; }, mpfr_mul);
    ties[wide] += exact;
    if (lp::kAvailable) {  // the top's x as FixedFloat reads it (top_rounded_into)
      F::Limb w[7];
      lp::multiply6_high(w, a.limbs().data(), b.limbs().data());
      const unsigned sh = static_cast<unsigned>(1 - (w[6] >> 63));
      const F::Limb r0 = (w[1] << sh) | ((w[0] >> 1) >> (63 - sh));
      top_undecided += !F::top_decides(r0 & ((F::Limb{1} << F::kSpare) - 1));
    }
  }
  for (mpz_ptr z : {A, B, target, t, mod, prod}) mpz_clear(z);
  CHECK(built >= kTries / 4);
  CHECK(checked == built);
  CHECK(ties[0] >= 40);
  CHECK(ties[1] >= 40);
  if (lp::kAvailable) CHECK(top_undecided >= built / 3);
  else WARN("the assembly is not run here: the products took GMP's whole product");
}

// The quotient by an integer below 2^32 is FixedFloat's own: a product by the divisor's reciprocal
// where the assembly runs, else (with IMPACT3D_GMP_PRODUCT set, the suite's second run, and for powers
// of two) a long division by a precomputed inverse; MPFR's division by a machine integer where the result
// leaves the fast range. Held here to mpfr_div on the integers those paths take, those just beyond them
// (2^32, a half-integer), numerators of every kind, down to where the quotient underflows, and exact
// multiples. (Whether a path is taken only speed shows.)
TEST_CASE("FixedFloat divided by an integer is MPFR's quotient, bit for bit", "[fixed_float]") {
  Draw d;
  // 2^31 + 1: its limb d = 2^63 + 2^32 lies far from its reciprocal's 2^128 / d, so the long division's
  // second correction (the estimate two short) is taken there, in the run that takes the long division.
  std::vector<double> divisors{1, -1, 2, 3, -3, 4, -4, 7, 90, -90, 180, -180, 360, 2147483648.0, 2147483649.0,
                               4294967295.0, -4294967295.0, 4294967296.0, 4294967297.0, 90.5, 0.5};
  for (int k = 0; k < 40; ++k) divisors.push_back(static_cast<double>(1 + d.g() % 4294967295ULL) * (k % 2 ? -1 : 1));
  std::vector<Mpfr> numerators(200);
  for (std::size_t k = 0; k < numerators.size(); ++k) {
    Mpfr spare;
    d.pair(numerators[k].x, spare.x);
  }
  mpfr_set_zero(numerators[0].x, 1), mpfr_set_zero(numerators[1].x, -1);
  mpfr_set_inf(numerators[2].x, -1), mpfr_set_nan(numerators[3].x);
  // The least number, 2^(emin - 1), and 3 times it: halved, quartered, divided by 3 or 7, the quotient
  // underflows, ties at half the least number (to zero) or rounds up to the least number.
  mpfr_set_ui_2exp(numerators[4].x, 1, mpfr_get_emin() - 1, MPFR_RNDN);
  mpfr_set_ui_2exp(numerators[5].x, 3, mpfr_get_emin() - 1, MPFR_RNDN);
  mpfr_set_ui_2exp(numerators[7].x, 7, mpfr_get_emin() + 1, MPFR_RNDN);
  mpfr_set_inf(numerators[6].x, 1), mpfr_nextbelow(numerators[6].x);  // the largest
  Mpfr n, want, exact;
  int checked = 0;
  for (const double v : divisors) {
    mpfr_set_d(n.x, v, MPFR_RNDN);
    const F b = F::of(n.x);
    for (const auto& a : numerators) {
      mpfr_div(want.x, a.x, n.x, MPFR_RNDN);
      INFO("a = " << mpfr_get_d(a.x, MPFR_RNDN) << ", b = " << v);
      REQUIRE(same(F::of(a.x) / b, want.x));
      ++checked;
    }
    // Multiples of the divisor: the quotient exact.
    for (int k = 0; k < 20; ++k) {
      d.significand(want.x);
      mpfr_prec_round(want.x, kP - 33, MPFR_RNDZ);
      mpfr_prec_round(want.x, kP, MPFR_RNDN);
      mpfr_mul_2si(want.x, want.x, static_cast<long>(d.g() % 41) - 20, MPFR_RNDN);
      REQUIRE(mpfr_mul(exact.x, want.x, n.x, MPFR_RNDN) == 0);  // a multiple in kP bits, exactly
      INFO("a = " << mpfr_get_d(exact.x, MPFR_RNDN) << ", b = " << v);
      REQUIRE(same(F::of(exact.x) / b, want.x));
      ++checked;
    }
  }
  CHECK(checked == 61 * (200 + 20));
}

// Sums whose exponents lie less than 64 apart are added in one carry chain and shifted by counts; the
// cases there that drawn pairs seldom reach, each held to MPFR (with the other operations on the pair):
// the guard limb deciding the rounding, a sum rounding up to the next power of two, and a difference
// shifted one place left that ties and rounds to a power of two.
TEST_CASE("FixedFloat's sums of nearby exponents at their rounding edges are MPFR's", "[fixed_float]") {
  Mpfr x, y;
  int checked = 0;
  for (long d = 48; d <= 63; ++d)
    for (unsigned long m : {1UL, 2UL, 3UL, 5UL, 7UL}) {
      mpfr_set_ui(x.x, 1, MPFR_RNDN), mpfr_mul_2si(x.x, x.x, kP, MPFR_RNDN), mpfr_sub_ui(x.x, x.x, m, MPFR_RNDN);
      mpfr_div_2si(x.x, x.x, kP, MPFR_RNDN);  // 1 - m 2^-kP
      mpfr_set_ui_2exp(y.x, 1, kP - 1, MPFR_RNDN), mpfr_add_ui(y.x, y.x, 1, MPFR_RNDN);
      mpfr_div_2si(y.x, y.x, kP + d, MPFR_RNDN);  // (1/2 + 2^-kP) 2^-d, its last bit below x's last place
      checked += agree_all(x.x, y.x) + agree_all(y.x, x.x);
    }
  // 1/2 + (1 - 2^-kP) / 2 = 1 - 2^-(kP + 1): a tie, to even, 1.
  mpfr_set_ui_2exp(x.x, 1, -1, MPFR_RNDN);
  mpfr_set_ui(y.x, 1, MPFR_RNDN), mpfr_nextbelow(y.x), mpfr_div_2ui(y.x, y.x, 1, MPFR_RNDN);
  checked += agree_all(x.x, y.x);
  // 5/8 - (1/8 + 2^-(kP + 2)) = 1/2 - 2^-(kP + 2): shifted one place left, a tie, to even, 1/2.
  mpfr_set_ui_2exp(x.x, 5, -3, MPFR_RNDN);
  mpfr_set_ui_2exp(y.x, 1, -3, MPFR_RNDN), mpfr_nextabove(y.x);
  REQUIRE(mpfr_cmp_ui_2exp(y.x, 1, -3) > 0);
  checked += agree_all(x.x, y.x);
  Mpfr want;
  mpfr_sub(want.x, x.x, y.x, MPFR_RNDN);
  CHECK(mpfr_cmp_ui_2exp(want.x, 1, -1) == 0);  // the case meant: it rounds to 1/2
  CHECK(checked == 4 * (16 * 5 * 2 + 2));
}

TEST_CASE("FixedFloat's conversions from integers and doubles are exact", "[fixed_float]") {
  std::mt19937_64 g(7);
  Mpfr want;
  int checked = 0;
  for (int k = 0; k < 10000; ++k) {
    const long long i = static_cast<long long>(g());
    mpfr_set_si(want.x, i, MPFR_RNDN);
    REQUIRE(same(F(i), want.x));
    const double v = std::bit_cast<double>(g());  // every double, subnormals, infinities and NaNs included
    mpfr_set_d(want.x, v, MPFR_RNDN);
    REQUIRE(same(F(v), want.x));
    REQUIRE((std::isnan(v) || static_cast<double>(F(v)) == v));
    ++checked;
  }
  for (const long long i : {0LL, 1LL, -1LL, std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max()}) {
    mpfr_set_si(want.x, i, MPFR_RNDN);
    REQUIRE(same(F(i), want.x));
  }
  mpfr_set_d(want.x, -0.0, MPFR_RNDN);
  REQUIRE(same(F(-0.0), want.x));
  CHECK(checked == 10000);
}

namespace {

using B = impact3d::mp::float100;

bool same_as_boost(const F& f, const B& b) { return same(f, b.backend().data()); }

}  // namespace

TEST_CASE("FixedFloat's sqrt, floor, atan2, hypot, abs and limits are Boost's MPFR numbers'", "[fixed_float]") {
  using std::numeric_limits;
  CHECK(same_as_boost(numeric_limits<F>::epsilon(), numeric_limits<B>::epsilon()));
  CHECK(same_as_boost(numeric_limits<F>::max(), (numeric_limits<B>::max)()));
  CHECK(same_as_boost(numeric_limits<F>::lowest(), numeric_limits<B>::lowest()));
  CHECK(same_as_boost(numeric_limits<F>::min(), (numeric_limits<B>::min)()));
  CHECK(same_as_boost(numeric_limits<F>::infinity(), numeric_limits<B>::infinity()));
  CHECK(same_as_boost(F::pi(), boost::math::constants::pi<B>()));
  CHECK(numeric_limits<F>::digits == numeric_limits<B>::digits);
  Draw d;
  Mpfr x, y;
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    d.pair(x.x, y.x);
    if (k % 7 == 0) mpfr_mul_2ui(y.x, x.x, 200, MPFR_RNDN);  // hypot's early return: x below y's last place
    if (k % 11 == 0) mpfr_set_zero(x.x, k % 2 ? 1 : -1);
    const F a = F::of(x.x), b = F::of(y.x);
    B ba, bb;
    mpfr_set(ba.backend().data(), x.x, MPFR_RNDN);
    mpfr_set(bb.backend().data(), y.x, MPFR_RNDN);
    REQUIRE(same_as_boost(sqrt(abs(a)), sqrt(abs(ba))));
    REQUIRE(same_as_boost(floor(a * F(1000)), floor(ba * B(1000))));
    REQUIRE(same_as_boost(atan2(a, b), atan2(ba, bb)));
    REQUIRE(same_as_boost(hypot(a, b), hypot(ba, bb)));
    if (k % 13 == 0) {  // an exact zero in either place, of either sign
      const F z = F(k % 2 ? 0.0 : -0.0);
      const B bz = B(k % 2 ? 0.0 : -0.0);
      REQUIRE(same_as_boost(hypot(z, b), hypot(bz, bb)));
      REQUIRE(same_as_boost(hypot(a, z), hypot(ba, bz)));
    }
    REQUIRE(same_as_boost(hypot(b, a), hypot(bb, ba)));
    REQUIRE(static_cast<double>(a) == static_cast<double>(ba));
    ++checked;
  }
  CHECK(checked == 20000);
}

// floor is FixedFloat's own for finite nonzero numbers below 2^P: held to mpfr_floor with the binary
// point at every place of the significand and just outside it, on significands with long runs of ones
// (a negative number's floor carrying into the next power of two), powers of two and few bits, both
// signs; and on zeros, infinities and NaN (MPFR's call).
TEST_CASE("FixedFloat's floor is mpfr_floor's at every place of the binary point", "[fixed_float]") {
  Draw d;
  Mpfr x, want;
  int checked = 0, mismatched = 0;
  for (long e = -3; e <= kP + 3; ++e)
    for (int k = 0; k < 60; ++k) {
      d.significand(x.x);
      mpfr_mul_2si(x.x, x.x, e, MPFR_RNDN);  // exponent e: the point after e bits
      mpfr_floor(want.x, x.x);
      if (!same(floor(F::of(x.x)), want.x)) ++mismatched, UNSCOPED_INFO("exponent " << e << ", draw " << k);
      ++checked;
    }
  for (const double v : {0.0, -0.0, 0.5, -0.5, 1.0, -1.0, -1.5, 2.0, -3.0}) {
    mpfr_set_d(x.x, v, MPFR_RNDN);
    mpfr_floor(want.x, x.x);
    if (!same(floor(F(v)), want.x)) ++mismatched, UNSCOPED_INFO("at " << v);
    ++checked;
  }
  for (const int sign : {1, -1}) {
    mpfr_set_inf(x.x, sign), mpfr_floor(want.x, x.x);
    mismatched += !same(floor(F::of(x.x)), want.x), ++checked;
  }
  mpfr_set_nan(x.x), mpfr_floor(want.x, x.x);
  mismatched += !same(floor(F::of(x.x)), want.x), ++checked;
  CHECK(mismatched == 0);
  CHECK(checked == (kP + 7) * 60 + 9 + 3);
}

TEST_CASE("FixedFloat's exact zeros carry Boost's signs whatever the operands' value categories", "[fixed_float]") {
  // Boost's numbers without expression templates subtract a temporary on the right in place, as
  // -(b - a), when GCC compiles them (under clang they have no overloads for temporaries), and a number
  // from a built-in one so too but for an integer a >= 0: an exact zero comes out -0 where a fresh
  // difference gives +0 (fixed_float.hpp). The expression shapes the kernels use and every built-in
  // shape, at values that cancel exactly, and hypot at zeros and NaN; CI runs it under GCC and clang.
  const double values[] = {0.0, -0.0, 1.0, -1.0, 0.375, 3.0};
  int checked = 0;
  for (const double x : values)
    for (const double y : values)
      for (const double z : values) {
        const F a(x), b(y), c(z);
        const B ba(x), bb(y), bc(z);
        REQUIRE(same_as_boost(a - b * c, ba - bb * bc));            // lvalue - temporary
        REQUIRE(same_as_boost(b * c - a, bb * bc - ba));            // temporary - lvalue
        REQUIRE(same_as_boost(a * c - b * c, ba * bc - bb * bc));  // temporary - temporary
        REQUIRE(same_as_boost(a - b, ba - bb));
        REQUIRE(same_as_boost(1 - a * b, 1 - ba * bb));  // a built-in number and a temporary
        REQUIRE(same_as_boost(1.0 - a, 1.0 - ba));
        REQUIRE(same_as_boost(1 - a, 1 - ba));  // an integer >= 0: mpfr_ui_sub, a plain difference
        REQUIRE(same_as_boost(-1 - a, -1 - ba));
        REQUIRE(same_as_boost(3u - a, 3u - ba));
        REQUIRE(same_as_boost(3u - a * b, 3u - ba * bb));
        REQUIRE(same_as_boost(-1 - a * b, -1 - ba * bb));
        REQUIRE(same_as_boost(1.0 - a * b, 1.0 - ba * bb));
        REQUIRE(same_as_boost(a * b - 1, ba * bb - 1));
        REQUIRE(same_as_boost(a - y, ba - y));
        REQUIRE(same_as_boost(a + b * c, ba + bb * bc));
        REQUIRE(same_as_boost(-(a - b), -(ba - bb)));
        REQUIRE(same_as_boost(hypot(a, b), hypot(ba, bb)));
        ++checked;
      }
  const F nan = std::numeric_limits<F>::quiet_NaN();
  const B bnan = std::numeric_limits<B>::quiet_NaN();
  CHECK(same_as_boost(hypot(nan, F(2)), hypot(bnan, B(2))));
  CHECK(same_as_boost(hypot(F(-0.0), nan), hypot(B(-0.0), bnan)));
  CHECK(checked == 216);
}

namespace {

// A collision's raw parameters at 100 digits: angles anywhere, and at the quarter turns and half-way
// between them, where sin_cos_deg's floors decide the quadrant.
impact3d::RawCollision<B> random_raw(std::mt19937_64& g, int k) {
  using namespace impact3d;
  std::uniform_real_distribution<double> u(0, 1);
  auto angle = [&](int j) {
    switch (j % 4) {
      case 0: return -1000 + 2000 * u(g);
      case 1: return 90.0 * static_cast<int>(g() % 17) - 720;
      case 2: return 45.0 + 90.0 * static_cast<int>(g() % 17) - 720;
      default: return -30 + 60 * u(g);
    }
  };
  RawCollision<B> raw;
  for (auto& v : raw.vehicle) {
    v.mass = B(700 + 2800 * u(g));
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) v.J_B(p, q) = B(p == q ? 3000 * u(g) + 300 : 200 * u(g) - 100);
    v.yaw_deg = B(angle(k)), v.pitch_deg = B(angle(k + 1)), v.roll_deg = B(angle(k + 2));
    for (int p = 0; p < 3; ++p) v.v_W(p) = B(40 * u(g) - 20), v.w_B(p) = B(u(g) - 0.5), v.p_CgIc_B(p) = B(4 * u(g) - 2);
  }
  raw.normal_yaw_deg = B(angle(k + 3)), raw.normal_pitch_deg = B(angle(k)), raw.tangent_roll_deg = B(angle(k + 1));
  raw.restitution = B(u(g));
  return raw;
}

bool identical(const B& a, const B& b) { return a == b ? signbit(a) == signbit(b) : (isnan(a) && isnan(b)); }
template <typename M>
bool identical_matrix(const M& m, const M& n) {
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (!identical(m(i, j), n(i, j))) return false;
  return true;
}
bool identical_optional(const std::optional<B>& a, const std::optional<B>& b) {
  return a.has_value() == b.has_value() && (!a || identical(*a, *b));
}

}  // namespace

TEST_CASE("The scene from raw parameters at 100 digits, computed in FixedFloat, is Boost's bit for bit", "[fixed_float]") {
  using namespace impact3d;
  std::mt19937_64 g(20261128);
  int checked = 0;
  for (int k = 0; k < 400; ++k) {
    const RawCollision<B> raw = random_raw(g, k);
    const Scene<B> twin = scene_of(raw), boost = compute_scene(raw);
    for (int i = 0; i < 2; ++i) {
      REQUIRE(identical_matrix(twin.body[i].R_WB, boost.body[i].R_WB));
      REQUIRE(identical_matrix(twin.body[i].J_B, boost.body[i].J_B));
    }
    REQUIRE(identical_matrix(twin.R_WC, boost.R_WC));
    ++checked;
  }
  CHECK(checked == 400);
}

// solve_lean from raw parameters stays in FixedFloat from the angles to the solution; the route it is held
// to computes the scene and the solve in Boost's numbers throughout (compute_scene, solve_lean_with).
TEST_CASE("solve_lean from raw parameters at 100 digits is the solve in Boost's numbers, bit for bit", "[fixed_float]") {
  using namespace impact3d;
  using namespace impact3d::test;
  std::mt19937_64 g(20261127);
  int compared = 0, solved = 0, not_approaching = 0;
  for (int k = 0; k < 60; ++k) {
    const RawCollision<B> raw = random_raw(g, k);
    const Scene<B> boost_scene = compute_scene(raw);
    for (const Strategy<double>& st_double : every_strategy(0.05 + 0.02 * k)) {
      const Strategy<B> st = convert_strategy<B>(st_double, [](double x) { return B(x); });
      for (Engine e : kEngines) {
        const LeanSolution<B> lean = solve_lean(raw, st, Want::velocities, e);
        const LeanSolution<B> boost = e == Engine::direct
                                          ? solve_lean_with<direct::DirectEngine>(boost_scene, st, Want::velocities)
                                          : solve_lean_with<GeneratedEngine>(boost_scene, st, Want::velocities);
        REQUIRE(lean.status == boost.status);
        CHECK(lean.warnings == boost.warnings);
        CHECK(lean.impulse.regime == boost.impulse.regime);
        CHECK(identical_matrix(lean.impulse.P_C, boost.impulse.P_C));
        CHECK(identical_optional(lean.impulse.gir, boost.impulse.gir));
        CHECK(identical_optional(lean.impulse.cir, boost.impulse.cir));
        CHECK(identical_optional(lean.impulse.mu_t_critical, boost.impulse.mu_t_critical));
        CHECK(identical_matrix(lean.P_W, boost.P_W));
        for (int i = 0; i < 2; ++i) CHECK((identical_matrix(lean.v_W[i], boost.v_W[i]) && identical_matrix(lean.w_B[i], boost.w_B[i])));
        ++compared;
        solved += lean.status == Status::solved;
        not_approaching += lean.status == Status::not_approaching;
      }
    }
  }
  CHECK(compared == 60 * static_cast<int>(every_strategy(0).size()) * 2);
  // Both outcomes met: roughly half the drawn collisions approach along the normal.
  CHECK(solved > 100);
  CHECK(not_approaching > 100);
}

}  // namespace check_fixed_float
