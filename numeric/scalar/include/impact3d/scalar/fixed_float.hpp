// A binary floating-point number of P bits held in fixed limbs, whose +, - and x and quotient by a small
// integer are rounded here, correctly to nearest (ties to even), whose floor (exact) is taken here too, and
// whose other operations are MPFR's own calls on it: the same value, bit for bit, as an MPFR number of
// precision P. It exists for speed alone. At 100 digits an MPFR call costs about as much in bookkeeping as in
// arithmetic (each operand's precision, thread-local flags and exponent range, a generic rounding), and
// Boost's number adds a zeroing constructor to every temporary (BENCHMARKS.md); here a product is the exact
// 2P-bit product (limb_product.hpp's assembly, or GMP's mpn_mul_n) rounded once, a sum the exact sum rounded
// once, a quotient by an integer below 2^32 the exact quotient rounded once: the definition MPFR implements.
// (Where the assembly runs, a product and a quotient are mostly rounded from the top of a product alone,
// where a bound on the rest shows it rounds the same: top_decides.) check_fixed_float holds every operation
// to MPFR's, and check_lean the lean route computed in it to analyze's in Boost's numbers.
//
// Layout as MPFR's: a regular value is 0.m x 2^e with the top bit of m set, the bits below P zero.
// Exponents stay within the fast range below, far inside MPFR's default [1 - 2^30, 2^30 - 1], which
// impact3d keeps; a result that would leave it, and every operation on an infinity or a NaN, is MPFR's
// call (which then overflows or underflows exactly as MPFR does).
//
// Written for the processor as much as for the reader (BENCHMARKS.md measures each step): the loops over
// limbs in x, +, -, the quotient and the rounding are unrolled (#pragma GCC unroll, which clang reads
// too), since at -O3 GCC otherwise vectorizes these short loops, moving limbs through the stack, where a
// limb stored alone and read back in a wider load stalls until the store completes; and in a product,
// in a sum of exponents less than 64 apart and in the rounding, the carry into a new place and the
// round-up are shifts and adds by 0 or 1 rather than branches, which random operands would mispredict
// half the time (the round-up's carry past the lowest limb, which they almost never take, is a branch).
#pragma once

#include <mpfr.h>

#include "impact3d/scalar/limb_product.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

namespace impact3d::mp {

template <int P>
class FixedFloat {
 public:
  using Limb = std::uint64_t;
  static constexpr int kLimbs = (P + 63) / 64;
  static constexpr int kSpare = 64 * kLimbs - P;  // the unused low bits of m[0]
  static_assert(P > 64 && kSpare >= 2, "room below the last place for the round bit");
  static constexpr std::int64_t kFastExponent = std::int64_t{1} << 28;
  enum Kind : std::uint8_t { kZero, kRegular, kInf, kNaN };

  FixedFloat() = default;  // +0, as an MPFR number Boost constructs
  FixedFloat(int v) { set_integer(v < 0, v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v)); }
  FixedFloat(long v) { set_integer(v < 0, v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v)); }
  FixedFloat(long long v) { set_integer(v < 0, v < 0 ? 0 - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v)); }
  FixedFloat(unsigned v) { set_integer(false, v); }
  FixedFloat(unsigned long v) { set_integer(false, v); }
  FixedFloat(unsigned long long v) { set_integer(false, v); }
  // Exact: a double has 53 bits.
  FixedFloat(double v) {
    if (std::isnan(v)) kind_ = kNaN;
    else if (std::isinf(v)) kind_ = kInf, neg_ = v < 0;
    else if (v == 0) neg_ = std::signbit(v);
    else {
      int e2;
      const double f = std::frexp(v, &e2);  // |f| in [1/2, 1)
      neg_ = f < 0;
      m_[kLimbs - 1] = static_cast<Limb>(std::ldexp(neg_ ? -f : f, 64));
      kind_ = kRegular, e_ = e2;
    }
  }

  // MPFR's view of this number: MPFR reads it, or writes a result of precision P into it.
  struct View {
    mpfr_t x;
    explicit View(const FixedFloat& f) {
      const int kind = f.kind_ == kZero ? MPFR_ZERO_KIND : f.kind_ == kRegular ? MPFR_REGULAR_KIND : f.kind_ == kInf ? MPFR_INF_KIND : MPFR_NAN_KIND;
      mpfr_custom_init_set(x, f.neg_ ? -kind : kind, static_cast<mpfr_exp_t>(f.e_), P, const_cast<Limb*>(f.m_.data()));
    }
  };
  // What MPFR wrote into a view of this number.
  void take(const View& v) {
    neg_ = mpfr_signbit(v.x) != 0;
    if (mpfr_nan_p(v.x)) kind_ = kNaN;
    else if (mpfr_inf_p(v.x)) kind_ = kInf;
    else if (mpfr_zero_p(v.x)) kind_ = kZero;
    else kind_ = kRegular, e_ = mpfr_get_exp(v.x);
  }
  // An MPFR number of precision P, exactly: its limbs copied where it is regular and of precision P (MPFR
  // keeps exactly kLimbs limbs then, the bits below P zero), else MPFR's mpfr_set.
  static FixedFloat of(mpfr_srcptr x) {
    FixedFloat r;
    if (mpfr_regular_p(x) && mpfr_get_prec(x) == P) {
      const Limb* d = static_cast<const Limb*>(mpfr_custom_get_significand(x));
      for (int i = 0; i < kLimbs; ++i) r.m_[i] = d[i];
      r.kind_ = kRegular, r.e_ = mpfr_custom_get_exp(x), r.neg_ = mpfr_signbit(x) != 0;
      return r;
    }
    View v(r);
    mpfr_set(v.x, x, MPFR_RNDN);
    r.take(v);
    return r;
  }
  // Into an MPFR number, rounded to its precision (exactly when it is P).
  void to(mpfr_ptr out) const {
    if (kind_ == kRegular && mpfr_get_prec(out) == P) {
      Limb* d = static_cast<Limb*>(mpfr_custom_get_significand(out));
      for (int i = 0; i < kLimbs; ++i) d[i] = m_[i];
      mpfr_custom_init_set(out, neg_ ? -MPFR_REGULAR_KIND : MPFR_REGULAR_KIND, static_cast<mpfr_exp_t>(e_), P, d);
      return;
    }
    const View v(*this);
    mpfr_set(out, v.x, MPFR_RNDN);
  }

  // f(result, a, b, rounding) or f(result, a, rounding): one MPFR call.
  template <typename F>
  static void call_into(FixedFloat& r, F f, const FixedFloat& a, const FixedFloat& b) {
    View v(r);
    const View va(a), vb(b);
    f(v.x, va.x, vb.x, MPFR_RNDN);
    r.take(v);
  }
  template <typename F>
  static FixedFloat call(F f, const FixedFloat& a, const FixedFloat& b) {
    FixedFloat r;
    call_into(r, f, a, b);
    return r;
  }
  template <typename F>
  static FixedFloat call(F f, const FixedFloat& a) {
    FixedFloat r;
    View v(r);
    const View va(a);
    f(v.x, va.x, MPFR_RNDN);
    r.take(v);
    return r;
  }

  Kind kind() const { return kind_; }
  bool negative() const { return neg_; }
  std::int64_t exponent() const { return e_; }
  const std::array<Limb, kLimbs>& limbs() const { return m_; }

  // The largest integer <= this: mpfr_floor's number (exact, as every floor is), computed here since
  // sin_cos_deg takes two an angle. The bits below the binary point cleared, and a negative number with
  // any of them set made one larger in magnitude; |x| < 1 gives +0 or -1; an infinity, a NaN, a zero and
  // a number of 2^P or more (an integer already) are MPFR's.
  FixedFloat floored() const {
    if (kind_ != kRegular || e_ >= P)
      return call([](mpfr_ptr r, mpfr_srcptr a, mpfr_rnd_t) { return mpfr_floor(r, a); }, *this);
    if (e_ <= 0) return neg_ ? FixedFloat(-1) : FixedFloat();
    const int cut = 64 * kLimbs - static_cast<int>(e_);  // bits below the point, 1 <= cut < 64 kLimbs
    FixedFloat out = *this;
    bool fraction = false;
    #pragma GCC unroll 16
    for (int i = 0; i < kLimbs; ++i) {
      const int below = cut - 64 * i;  // of limb i's bits, how many lie below the point
      const Limb mask = below >= 64 ? ~Limb{0} : below <= 0 ? Limb{0} : (Limb{1} << below) - 1;
      fraction = fraction || (out.m_[i] & mask) != 0;
      out.m_[i] &= ~mask;
    }
    if (neg_ && fraction) {  // one more in magnitude: 2^cut added to the limbs
      Limb* from = out.m_.data() + cut / 64;
      if (mpn_add_1(from, from, kLimbs - cut / 64, Limb{1} << (cut % 64)) != 0) {
        // every kept bit was one: the next power of two
        out.m_[kLimbs - 1] = Limb{1} << 63;
        ++out.e_;
      }
    }
    return out;
  }

  friend FixedFloat operator-(FixedFloat a) {
    a.neg_ = !a.neg_;
    return a;
  }
  // Every path writes the one result object (returned in place: a copy of a number just written limb by
  // limb is read back wider than it was stored, which stalls). Out of line, as add: a kernel makes
  // hundreds of these calls.
  [[gnu::noinline]] friend FixedFloat operator*(const FixedFloat& a, const FixedFloat& b) {
    FixedFloat out;
    if (a.kind_ == kRegular && b.kind_ == kRegular) {
      if constexpr (kLimbs == 6 && kSpare >= 8) {
        if (limb_product::kAvailable &&
            top_rounded_into(out, a.m_.data(), b.m_.data(), a.e_ + b.e_, a.neg_ != b.neg_))
          return out;
      }
      Limb p[2 * kLimbs];
      product(p, a, b);
      // The product lies in [1/2, 1) (top bit set: t = 1) or in [1/4, 1/2) (t = 0: one place more).
      // Selected by shifts, not a branch: random operands would mispredict it half the time.
      const Limb t = p[2 * kLimbs - 1] >> 63;
      const unsigned sh = static_cast<unsigned>(1 - t);
      Limb r[kLimbs];
      shifted_left(r, p + kLimbs - 1, sh);
      Limb below = p[kLimbs - 1] << sh;
      #pragma GCC unroll 16
      for (int i = 0; i < kLimbs - 1; ++i) below |= p[i];
      if (!round_into(out, r, below != 0, a.e_ + b.e_ - static_cast<std::int64_t>(sh), a.neg_ != b.neg_))
        call_into(out, mpfr_mul, a, b);
    } else if ((a.kind_ == kZero && b.kind_ <= kRegular) || (b.kind_ == kZero && a.kind_ <= kRegular)) {
      out.neg_ = a.neg_ != b.neg_;
    } else {
      call_into(out, mpfr_mul, a, b);
    }
    return out;
  }
  friend FixedFloat operator+(const FixedFloat& a, const FixedFloat& b) { return add(a, b, false); }
  friend FixedFloat operator-(const FixedFloat& a, const FixedFloat& b) { return add(a, b, true); }
  // Boost's numbers without expression templates (no_et_ops.hpp, mpfr.hpp, default_ops.hpp's
  // eval_subtract_default) give the same value as a plain difference but for the sign of an exact zero:
  // where they compute -(b - a), it comes out -0 rather than +0. They do so for a temporary on the right
  // (subtracted in place), and for a number on the right of a built-in one, but for an integer a >= 0
  // (mpfr_ui_sub: plain). Their overloads for temporaries exist only where the compiler does not call
  // itself GCC 4.4 or older (no_et_ops.hpp's guard); clang calls itself GCC 4.2, so under clang a
  // temporary is taken as a reference like any number. Two temporaries, or a built-in number on the
  // right: plain, either way. check_fixed_float holds every shape to Boost's, and CI runs it under GCC
  // and clang.
#if defined(__GNUC__) && __GNUC__ == 4 && __GNUC_MINOR__ < 5
  static constexpr bool kBoostTakesTemporaries = false;
#else
  static constexpr bool kBoostTakesTemporaries = true;
#endif
  template <typename V>
  static FixedFloat builtin_minus(V a, const FixedFloat& b) {
    if constexpr (std::is_unsigned_v<V>) {
      return add(FixedFloat(a), b, true);
    } else if constexpr (std::is_integral_v<V>) {
      if (a >= 0) return add(FixedFloat(a), b, true);
    }
    return -add(b, FixedFloat(a), true);
  }
  friend FixedFloat operator-(const FixedFloat& a, FixedFloat&& b) {
    if constexpr (kBoostTakesTemporaries) return -add(b, a, true);
    else return add(a, b, true);
  }
  friend FixedFloat operator-(FixedFloat&& a, FixedFloat&& b) { return add(a, b, true); }
  template <typename V>
    requires std::is_arithmetic_v<V>
  friend FixedFloat operator-(V a, FixedFloat&& b) {
    if constexpr (kBoostTakesTemporaries) return -add(b, FixedFloat(a), true);
    else return builtin_minus(a, b);
  }
  template <typename V>
    requires std::is_arithmetic_v<V>
  friend FixedFloat operator-(V a, const FixedFloat& b) {
    return builtin_minus(a, b);
  }
  template <typename V>
    requires std::is_arithmetic_v<V>
  friend FixedFloat operator-(const FixedFloat& a, V b) {
    return add(a, FixedFloat(b), true);
  }
  template <typename V>  // without it, a temporary minus a built-in number is ambiguous under ISO C++
    requires std::is_arithmetic_v<V>
  friend FixedFloat operator-(FixedFloat&& a, V b) {
    return add(a, FixedFloat(b), true);
  }
  // By an integer divisor below 2^32 (the 90 and 180 of every angle's reduction): the quotient rounded
  // once (quotient_by_limb), so mpfr_div's number, in a fraction of the time; a zero numerator,
  // or a quotient leaving the fast range, MPFR's division by a machine integer. Every path writes the
  // one result object, as operator* does.
  friend FixedFloat operator/(const FixedFloat& a, const FixedFloat& b) {
    FixedFloat out;
    if (a.kind_ <= kRegular && b.kind_ == kRegular && b.e_ >= 1 && b.e_ <= 32 && (b.m_[kLimbs - 1] << b.e_) == 0 &&
        b.low_limbs_zero()) {
      if (a.kind_ == kRegular && quotient_by_limb(out, a, b.m_[kLimbs - 1], static_cast<int>(b.e_), a.neg_ != b.neg_)) return out;
      const unsigned long u = b.m_[kLimbs - 1] >> (64 - b.e_);
      View v(out);
      const View va(a);
      mpfr_div_ui(v.x, va.x, u, MPFR_RNDN);
      out.take(v);
      if (b.neg_) out.neg_ = !out.neg_;
      return out;
    }
    call_into(out, mpfr_div, a, b);
    return out;
  }
  FixedFloat& operator+=(const FixedFloat& b) { return *this = *this + b; }
  FixedFloat& operator-=(const FixedFloat& b) { return *this = *this - b; }
  FixedFloat& operator*=(const FixedFloat& b) { return *this = *this * b; }
  FixedFloat& operator/=(const FixedFloat& b) { return *this = *this / b; }

  // -1, 0, 1 as a < b, a == b, a > b; 2 unordered (a NaN).
  friend int compare(const FixedFloat& a, const FixedFloat& b) {
    if (a.kind_ == kNaN || b.kind_ == kNaN) return 2;
    if (a.kind_ == kZero && b.kind_ == kZero) return 0;
    const int sa = a.sign(), sb = b.sign();
    if (sa != sb) return sa < sb ? -1 : 1;
    const int mag = compare_magnitude(a, b);
    return sa < 0 ? -mag : mag;
  }
  friend bool operator==(const FixedFloat& a, const FixedFloat& b) { return compare(a, b) == 0; }
  friend bool operator!=(const FixedFloat& a, const FixedFloat& b) { return compare(a, b) != 0; }
  friend bool operator<(const FixedFloat& a, const FixedFloat& b) { return compare(a, b) == -1; }
  friend bool operator>(const FixedFloat& a, const FixedFloat& b) { return compare(a, b) == 1; }
  friend bool operator<=(const FixedFloat& a, const FixedFloat& b) { return static_cast<unsigned>(compare(a, b) + 1) <= 1; }
  friend bool operator>=(const FixedFloat& a, const FixedFloat& b) { return static_cast<unsigned>(compare(a, b)) <= 1; }

  explicit operator double() const {
    const View v(*this);
    return mpfr_get_d(v.x, MPFR_RNDN);
  }
  explicit operator bool() const { return kind_ != kZero; }

  // 2^k, k + 1 within MPFR's exponent range: 0.1 x 2^(k + 1), as mpfr_set_ui_2exp writes it.
  static FixedFloat power_of_two(std::int64_t k) {
    FixedFloat r;
    r.m_[kLimbs - 1] = Limb{1} << 63;
    r.kind_ = kRegular, r.e_ = k + 1;
    return r;
  }

  static FixedFloat pi() {
    FixedFloat r;
    View v(r);
    mpfr_const_pi(v.x, MPFR_RNDN);
    r.take(v);
    return r;
  }

  // Whether a product whose top T (limb_product::multiply6_high), normalized, leaves `x` below the last
  // place (the round bit and the kSpare - 1 bits under it) rounds as T alone would. The whole product
  // lies in [T, T + 5 * 2^384) (the 15 limb products left out), a quotient read as a product (in
  // quotient_by_limb) in [T, T + 6 * 2^384): so, after the normalizing shift and with T's own bits
  // under x, in [x, x + 13) units of x's lowest bit. It rounds as x does unless that range could reach
  // the tie: x in [half - 12, half]; 16 for 12 leaves a margin. (A range that carries into the last
  // place rounds up as x does: the rest is then far below half.) At 334 bits random products land
  // there about once in 2^45, a quotient never (quotient_by_limb), and an exact product of short
  // operands (doubles', integers') at x = 0, away from it. Public for check_fixed_float.
  static constexpr bool top_decides(Limb x) {
    static_assert(kSpare >= 8, "room below the last place for the slop");
    constexpr Limb half = Limb{1} << (kSpare - 1), slop = 16;
    return x < half - slop || x > half;
  }

 private:
  std::array<Limb, kLimbs> m_{};  // m_[kLimbs - 1] most significant
  std::int64_t e_ = 0;
  Kind kind_ = kZero;
  bool neg_ = false;

  int sign() const { return kind_ == kZero ? 0 : neg_ ? -1 : 1; }
  bool low_limbs_zero() const {
    for (int i = 0; i < kLimbs - 1; ++i)
      if (m_[i] != 0) return false;
    return true;
  }

  void set_integer(bool neg, std::uint64_t v) {
    neg_ = neg;
    if (v == 0) return;
    const int z = std::countl_zero(v);
    m_[kLimbs - 1] = v << z;  // 64 bits fit in P
    kind_ = kRegular, e_ = 64 - z;
  }

  // |a| against |b|, both neither NaN.
  static int compare_magnitude(const FixedFloat& a, const FixedFloat& b) {
    if (a.kind_ != b.kind_) {
      const int ra = a.kind_ == kZero ? 0 : a.kind_ == kRegular ? 1 : 2, rb = b.kind_ == kZero ? 0 : b.kind_ == kRegular ? 1 : 2;
      return ra < rb ? -1 : 1;
    }
    if (a.kind_ != kRegular) return 0;
    if (a.e_ != b.e_) return a.e_ < b.e_ ? -1 : 1;
    for (int i = kLimbs - 1; i >= 0; --i)
      if (a.m_[i] != b.m_[i]) return a.m_[i] < b.m_[i] ? -1 : 1;
    return 0;
  }

  // The exact 2P-bit product of the significands: in registers by limb_product.hpp's assembly where the
  // processor has it (six limbs), else GMP's.
  static void product(Limb (&p)[2 * kLimbs], const FixedFloat& a, const FixedFloat& b) {
    if constexpr (kLimbs == 6) {
      if (limb_product::kAvailable) limb_product::multiply6(p, a.m_.data(), b.m_.data());
      else gmp_product(p, a, b);
    } else {
      gmp_product(p, a, b);
    }
  }
  // 0.a x 0.b x 2^e, rounded from its top 21 limb products where top_decides says they decide it (a
  // product's e the sum of its exponents; quotient_by_limb's reads its quotient so); false else.
  static bool top_rounded_into(FixedFloat& out, const Limb* a, const Limb* b, std::int64_t e, bool neg) {
    Limb w[7];
    limb_product::multiply6_high(w, a, b);
    const unsigned sh = static_cast<unsigned>(1 - (w[6] >> 63));
    Limb r[kLimbs];
    shifted_left(r, w, sh);
    if (!top_decides(r[0] & ((Limb{1} << kSpare) - 1))) [[unlikely]] return false;
    // The sticky bit matters only on a tie, which top_decides has ruled out.
    return round_into(out, r, false, e - static_cast<std::int64_t>(sh), neg);
  }
  [[gnu::noinline]] static void gmp_product(Limb (&p)[2 * kLimbs], const FixedFloat& a, const FixedFloat& b) {
    Limb w[2 * kLimbs];
    if (&a == &b) mpn_sqr(w, a.m_.data(), kLimbs);
    else mpn_mul_n(w, a.m_.data(), b.m_.data(), kLimbs);
    // GMP stored the product limb by limb: read it so, not in wider vector loads that would wait on
    // those stores (each limb through a register).
    #pragma GCC unroll 16
    for (int k = 0; k < 2 * kLimbs; ++k) p[k] = in_register(w[k]);
  }

  static Limb in_register(Limb x) {
    asm("" : "+r"(x));
    return x;
  }

  // r = limbs src[1 .. kLimbs] shifted left by c places, 0 <= c < 64, src[0]'s top c bits coming in:
  // how a product, a quotient and a difference bring their leading one to the top.
  static void shifted_left(Limb (&r)[kLimbs], const Limb* src, unsigned c) {
    #pragma GCC unroll 16
    for (int i = 0; i < kLimbs; ++i) r[i] = (src[i + 1] << c) | ((src[i] >> 1) >> (63 - c));
  }

  // The exact value (0.r + below) x 2^e rounded to nearest, ties to even, written into `out`: r holds the
  // kLimbs limbs from the leading one, `sticky` whether anything nonzero lies below them. The limbs stay
  // in registers and are stored once (a number written limb by limb and read back in wider loads
  // stalls), and the round-up is added rather than branched on (only its rare carry past the lowest limb
  // is a branch). False where the result leaves the fast exponent range (MPFR's call then decides it).
  static bool round_into(FixedFloat& out, Limb (&r)[kLimbs], bool sticky, std::int64_t e, bool neg) {
    constexpr Limb half = Limb{1} << (kSpare - 1), below = half - 1;
    const Limb up = ((r[0] & half) != 0) & (sticky | ((r[0] & below) != 0) | ((r[0] >> kSpare) & 1));
    r[0] &= ~((half << 1) - 1);
    r[0] += up << kSpare;
    // The round-up carries out of the lowest limb only where its kept bits were all ones and it rounds up
    // (about once in 2^(65 - kSpare) for random operands): a branch nearly never taken, where a carry
    // chain through every limb would make every rounding wait for it.
    if (r[0] < (up << kSpare)) [[unlikely]] {
      if (mpn_add_1(r + 1, r + 1, kLimbs - 1, 1) != 0) {  // 0.111...1 rounded up to 1: 0.1 x 2^(e + 1)
        r[kLimbs - 1] = Limb{1} << 63;
        ++e;
      }
    }
    if (e > kFastExponent || e < -kFastExponent) return false;
    #pragma GCC unroll 16
    for (int i = 0; i < kLimbs; ++i) out.m_[i] = in_register(r[i]);
    out.kind_ = kRegular, out.e_ = e, out.neg_ = neg;
    return true;
  }

  // a / u, a regular, u an integer of k bits, 1 <= k <= 32, whose limb shifted to the top is d. Where the
  // assembly runs, first as a product: a's limbs times R = floor(2^447 / d), whose top decides the rounding
  // (top_decides) wherever the quotient lies more than 13 units of x from a tie, so at 334 bits always
  // (below: 2^49 / u >= 2^17 units at least). Else, and for u = 2^j, the exact quotient of a's limbs with a
  // zero limb below them, taken limb by limb with d's precomputed inverse (Moeller and Granlund, "Improved
  // division by invariant integers", 2011, algorithm 4; dividend and divisor shifted alike, which leaves the
  // quotient), rounded with the remainder in the sticky bit. That quotient has at least 64 (kLimbs + 1) - 33
  // bits, more than P + 1, so the round bit lies in it, and below it the sticky bit: the quotient's lower
  // bits and the remainder. (Where kSpare > 33, as at 334 bits, the lower bits decide it alone: a quotient by
  // u lies at least 1/(2u) of a last place from a tie, or on it exactly when the remainder is zero, and a tie
  // cannot be: its P + 1 bits times u would not fit in P.)
  [[gnu::noinline]] static bool quotient_by_limb(FixedFloat& out, const FixedFloat& a, Limb d, int k, bool neg) {
    if constexpr (kLimbs == 6 && kSpare >= 8) {
      if (limb_product::kAvailable && d != Limb{1} << 63) {
        // A 2^447 / d (a's limbs A; the quotient's significand times 2^767, in [2^766, 2^768) as a
        // product's) lies in [A R, A R + A), A < 2^384, so in [T, T + 6 * 2^384). u = 2^j (d = 2^63)
        // would need R = 2^384, a limb more, and takes the long division. R is kept per thread: a
        // collision divides by 90 and by 180, which share d (45 at the top).
        struct Reciprocal {
          Limb d, r[7];
        };
        thread_local Reciprocal kept{};
        if (kept.d != d) {
          const Limb two_447[7] = {0, 0, 0, 0, 0, 0, Limb{1} << 63};
          mpn_divrem_1(kept.r, 0, two_447, 7, d);  // r[6] = 0: d > 2^63
          kept.d = d;
        }
        // a / u = 0.A x 0.R x 2^(e_a - k + 1).
        if (top_rounded_into(out, a.m_.data(), kept.r, a.e_ - k + 1, neg)) [[likely]] return true;
      }
    }
    using Wide = unsigned __int128;
    const Limb v = static_cast<Limb>(((static_cast<Wide>(~d) << 64) | ~Limb{0}) / d);
    constexpr int n = kLimbs + 2;
    const int sh = 64 - k;
    Limb num[n];  // the limbs, a zero limb, shifted left by sh: num[n - 1] < d
    num[0] = 0;
    num[1] = a.m_[0] << sh;
    #pragma GCC unroll 16
    for (int j = 2; j < n - 1; ++j) num[j] = (a.m_[j - 1] << sh) | (a.m_[j - 2] >> k);
    num[n - 1] = a.m_[kLimbs - 1] >> k;
    Limb q[n - 1], rem = num[n - 1];
    #pragma GCC unroll 16
    for (int j = n - 2; j >= 0; --j) {
      const Wide t = static_cast<Wide>(v) * rem + ((static_cast<Wide>(rem) << 64) | num[j]);
      Limb q1 = static_cast<Limb>(t >> 64) + 1;
      const Limb q0 = static_cast<Limb>(t);
      Limb r = num[j] - q1 * d;
      const Limb over = Limb{0} - static_cast<Limb>(r > q0);  // the estimate one too large
      q1 += over, r += over & d;
      if (r >= d) ++q1, r -= d;  // rare
      q[j] = q1, rem = r;
    }
    const int c = std::countl_zero(q[n - 2]);  // q[n - 2] holds the quotient's top bits: not zero
    Limb r[kLimbs];
    shifted_left(r, q, static_cast<unsigned>(c));
    const bool sticky = (q[0] << c) != 0 || rem != 0;
    return round_into(out, r, sticky, a.e_ - c, neg);
  }

  // a + b, or a - b when `subtract`, written into the one result object as operator* does.
  [[gnu::noinline]] static FixedFloat add(const FixedFloat& a, const FixedFloat& b, bool subtract) {
    FixedFloat out;
    const bool nb = b.neg_ != subtract;
    if (a.kind_ == kRegular && b.kind_ == kRegular) {
      const bool b_larger = compare_magnitude(a, b) < 0;
      const FixedFloat& x = b_larger ? b : a;  // |x| >= |y|
      const FixedFloat& y = b_larger ? a : b;
      const bool nx = b_larger ? nb : a.neg_, ny = b_larger ? a.neg_ : nb;
      const std::int64_t d = x.e_ - y.e_;
      if (d > P + 1) {
        // |y| < 2^(e_x - P - 2), a quarter of x's last place and below half of the place under x (x a
        // power of two): the sum rounds to x either way.
        out.m_ = x.m_, out.kind_ = kRegular, out.e_ = x.e_, out.neg_ = nx;
        return out;
      }
      if (!sum_into(out, x, y, d, nx, nx != ny)) call_into(out, subtract ? mpfr_sub : mpfr_add, a, b);
    } else if (a.kind_ <= kRegular && b.kind_ <= kRegular) {
      // A zero: the other operand exactly; two zeros: -0 only when both are negative.
      if (b.kind_ == kZero) {
        out = a;
        if (a.kind_ == kZero) out.neg_ = a.neg_ && nb;
      } else {
        out = b;
        out.neg_ = nb;
      }
    } else {
      call_into(out, subtract ? mpfr_sub : mpfr_add, a, b);
    }
    return out;
  }

  // x + y (or x - y when `differ`), |x| >= |y| both regular, d = e_x - e_y <= P + 1, with x's sign `nx`.
  static bool sum_into(FixedFloat& out, const FixedFloat& x, const FixedFloat& y, std::int64_t d, bool nx, bool differ) {
    return d < 64 ? sum_near(out, x, y, static_cast<unsigned>(d), nx, differ) : sum_far(out, x, y, d, nx, differ);
  }

  // sum_into where d < 64, as nearly every sum of a kernel is: y shifted by d within x's limbs and a guard
  // limb below them, nothing below that. Added, or subtracted as x + ~y + 1, in one carry chain, and
  // the result shifted one place right (a sum in [1, 2)) or left (a difference in [1/4, 1/2)) by shift
  // counts rather than branches: random signs and magnitudes would mispredict them. A difference that
  // cancelled further (d <= 1) is sum_far's.
  static bool sum_near(FixedFloat& out, const FixedFloat& x, const FixedFloat& y, unsigned d, bool nx, bool differ) {
    using Wide = unsigned __int128;
    constexpr int n = kLimbs + 1;
    Limb v[n];
    v[0] = (y.m_[0] << 1) << (63 - d);
    #pragma GCC unroll 16
    for (int j = 1; j < kLimbs; ++j) v[j] = (y.m_[j - 1] >> d) | ((y.m_[j] << 1) << (63 - d));
    v[n - 1] = y.m_[kLimbs - 1] >> d;
    const Limb flip = Limb{0} - static_cast<Limb>(differ);
    Limb sum[n], carry = static_cast<Limb>(differ);
    #pragma GCC unroll 16
    for (int j = 0; j < n; ++j) {
      const Wide t = static_cast<Wide>(j == 0 ? Limb{0} : x.m_[j - 1]) + (v[j] ^ flip) + carry;
      sum[j] = static_cast<Limb>(t), carry = static_cast<Limb>(t >> 64);
    }
    // A difference always carries out. Shifted right, nothing is lost: y's bits below its last place
    // are zero, so the guard limb's lowest bit is.
    const Limb right = carry & static_cast<Limb>(!differ);
    #pragma GCC unroll 16
    for (int j = 0; j < n - 1; ++j) sum[j] = (sum[j] >> right) | ((sum[j + 1] << 1) << (63 - right));
    sum[n - 1] = (sum[n - 1] >> right) | (right << 63);
    if ((sum[n - 1] >> 62) == 0) return sum_far(out, x, y, d, nx, differ);
    const Limb left = 1 - (sum[n - 1] >> 63);
    Limb r[kLimbs];
    shifted_left(r, sum, static_cast<unsigned>(left));
    return round_into(out, r, (sum[0] << left) != 0, x.e_ + static_cast<std::int64_t>(right) - static_cast<std::int64_t>(left), nx);
  }

  // sum_into for any d: y shifted by whole limbs and bits, and whatever fell below the guard limb kept
  // as a sticky bit.
  static bool sum_far(FixedFloat& out, const FixedFloat& x, const FixedFloat& y, std::int64_t d, bool nx, bool differ) {
    // In kLimbs + 1 limbs, x's and a guard limb below them: y shifted right by d, and whether any of
    // its bits fell below the guard limb (y holds at most kLimbs limbs, so d < 64 makes none fall).
    using Wide = unsigned __int128;
    constexpr int n = kLimbs + 1;
    Limb yd[n], sum[n];
    const int q = static_cast<int>(d / 64), s = static_cast<int>(d % 64);
    // y's limb i sits in limb i + 1 before the shift; source(k) is that layout's limb k.
    auto source = [&](int k) { return k >= 1 && k <= kLimbs ? y.m_[k - 1] : Limb{0}; };
    #pragma GCC unroll 16
    for (int j = 0; j < n; ++j) yd[j] = (source(j + q) >> s) | ((source(j + q + 1) << 1) << (63 - s));
    bool sticky = ((source(q) << 1) << (63 - s)) != 0;  // the low s bits of limb q
    for (int k = 1; k < q && !sticky; ++k) sticky = source(k) != 0;
    std::int64_t e = x.e_;
    if (!differ) {
      Limb carry = 0;
      sum[0] = yd[0];
      #pragma GCC unroll 16
      for (int j = 1; j < n; ++j) {
        const Wide t = static_cast<Wide>(x.m_[j - 1]) + yd[j] + carry;
        sum[j] = static_cast<Limb>(t), carry = static_cast<Limb>(t >> 64);
      }
      if (carry) {  // in [1, 2): one place right, the bit shifted out of the guard limb into the sticky
        sticky = sticky || (sum[0] & 1);
        #pragma GCC unroll 16
        for (int j = 0; j < n - 1; ++j) sum[j] = (sum[j] >> 1) | (sum[j + 1] << 63);
        sum[n - 1] = (sum[n - 1] >> 1) | (Limb{1} << 63);
        ++e;
      }
    } else {
      // x - y exactly is the difference of the n limbs less a fraction of the guard limb's last place
      // when bits fell below it: the difference less one whole place, plus a fraction in (0, 1).
      Limb borrow = sticky ? 1 : 0;
      #pragma GCC unroll 16
      for (int j = 0; j < n; ++j) {
        const Wide t = static_cast<Wide>(j == 0 ? Limb{0} : x.m_[j - 1]) - yd[j] - borrow;
        sum[j] = static_cast<Limb>(t), borrow = static_cast<Limb>(t >> 64) & 1;
      }
      // |x| > |y| leaves a positive difference. With d >= 2 it exceeds |x| / 2: one place at most to
      // shift. With d <= 1 nothing fell below (sticky false) and the difference is exact in n limbs,
      // however far it cancelled.
      int top = n - 1;
      while (top >= 0 && sum[top] == 0) --top;
      if (top < 0) {  // x - x: +0 to nearest
        out.kind_ = kZero, out.neg_ = false;
        return true;
      }
      const int c = std::countl_zero(sum[top]);
      const int shift = 64 * (n - 1 - top) + c;
      const int lq = shift / 64, ls = shift % 64;
      #pragma GCC unroll 16
      for (int j = n - 1; j >= 0; --j) {
        const Limb hi = j - lq >= 0 ? sum[j - lq] : 0, lo = j - lq - 1 >= 0 ? sum[j - lq - 1] : 0;
        sum[j] = (hi << ls) | ((lo >> 1) >> (63 - ls));
      }
      e -= shift;
    }
    Limb r[kLimbs];
    #pragma GCC unroll 16
    for (int k = 0; k < kLimbs; ++k) r[k] = sum[k + 1];
    return round_into(out, r, sticky || sum[0] != 0, e, nx);
  }
};

template <int P>
FixedFloat<P> abs(const FixedFloat<P>& x) {
  return x.negative() ? -x : x;
}
template <int P>
FixedFloat<P> fabs(const FixedFloat<P>& x) {
  return abs(x);
}
template <int P>
FixedFloat<P> sqrt(const FixedFloat<P>& x) {
  return FixedFloat<P>::call(mpfr_sqrt, x);
}
template <int P>
FixedFloat<P> log(const FixedFloat<P>& x) {
  return FixedFloat<P>::call(mpfr_log, x);
}
template <int P>
FixedFloat<P> floor(const FixedFloat<P>& x) {
  return x.floored();
}
template <int P>
FixedFloat<P> atan2(const FixedFloat<P>& y, const FixedFloat<P>& x) {
  return FixedFloat<P>::call(mpfr_atan2, y, x);
}
// Not MPFR's correctly rounded mpfr_hypot: Boost.Multiprecision's (1.74, default_ops.hpp eval_hypot), step
// by step, which is what its MPFR numbers compute and what this type must reproduce.
template <int P>
FixedFloat<P> hypot(FixedFloat<P> x, FixedFloat<P> y) {
  using F = FixedFloat<P>;
  // Boost negates an argument whose sign is negative: not -0 (sign 0) nor a NaN.
  if (x.negative() && (x.kind() == F::kRegular || x.kind() == F::kInf)) x = -x;
  if (y.negative() && (y.kind() == F::kRegular || y.kind() == F::kInf)) y = -y;
  if (x.kind() == F::kZero) return y;
  if (y.kind() == F::kZero) return x;
  if (x.kind() == F::kInf) return x;
  if (y.kind() >= F::kInf) return y;
  if (x.kind() == F::kNaN) return x;
  if (y > x) std::swap(x, y);
  if (x * std::numeric_limits<F>::epsilon() > y) return x;
  const F rat = y / x;
  return sqrt(rat * rat + F(1)) * x;
}
template <int P>
bool isfinite(const FixedFloat<P>& x) {
  return x.kind() <= FixedFloat<P>::kRegular;
}
template <int P>
bool isnan(const FixedFloat<P>& x) {
  return x.kind() == FixedFloat<P>::kNaN;
}
template <int P>
bool isinf(const FixedFloat<P>& x) {
  return x.kind() == FixedFloat<P>::kInf;
}
template <int P>
bool signbit(const FixedFloat<P>& x) {
  return x.negative();
}

}  // namespace impact3d::mp

template <int P>
class std::numeric_limits<impact3d::mp::FixedFloat<P>> {
  using F = impact3d::mp::FixedFloat<P>;

 public:
  static constexpr bool is_specialized = true, is_signed = true, is_integer = false, is_exact = false;
  static constexpr bool has_infinity = true, has_quiet_NaN = true, is_iec559 = false, is_bounded = true;
  static constexpr int radix = 2, digits = P;
  static constexpr int digits10 = static_cast<int>((P - 1) * 301LL / 1000);
  static constexpr int max_digits10 = static_cast<int>(P * 301LL / 1000) + 2;
  static constexpr std::float_round_style round_style = std::round_to_nearest;
  static F epsilon() { return F::power_of_two(1 - P); }
  static F infinity() { return F(HUGE_VAL); }
  static F quiet_NaN() { return F(std::numeric_limits<double>::quiet_NaN()); }
  // As Boost states it for its MPFR numbers (the number this type stands in for): 2^(emax - 1).
  static F max() { return F::power_of_two(mpfr_get_emax() - 1); }
  static F lowest() { return -max(); }
  static F min() { return F::power_of_two(mpfr_get_emin() - 1); }
};
