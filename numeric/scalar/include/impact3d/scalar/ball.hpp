// A certified scalar (issue 14): Arb's midpoint-radius ball, whose enclosure of the exact value is
// guaranteed through +, -, x, /, sqrt, hypot, sin, cos, atan2 and acos. The mechanics run on it through
// the same templated code as on every other scalar; the working precision is the thread's BallBits.
//
// Comparisons. <, <=, > and >= are decisions: certain when the ball of the difference lies on one side
// of zero; otherwise they take the midpoints' branch (false where a midpoint is NaN, as for IEEE
// numbers; for the name a DecisionLog flips, the other) and, while a log is installed, record the
// decision as undecided (decisions.hpp). == and != ask
// whether two balls are the same exact number, which is what the mechanics' tests for an exact zero or
// an exact quarter turn mean. floor() takes the midpoint's floor, an exact integer: the mechanics use it
// only where any integer is correct (a reduction by whole turns) or for a clock position.
#pragma once

#include <mpfr.h>

#include <arb.h>

#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "impact3d/scalar/decision_log.hpp"
#include "impact3d/scalar/sin_cos_radians.hpp"
#include "impact3d/scalar/types.hpp"

namespace impact3d {

// The working precision of this thread's ball arithmetic, in bits.
inline thread_local long ball_bits = 256;

class BallBits {
 public:
  explicit BallBits(long bits) : previous_(ball_bits) { ball_bits = bits; }
  ~BallBits() { ball_bits = previous_; }
  BallBits(const BallBits&) = delete;
  BallBits& operator=(const BallBits&) = delete;

 private:
  long previous_;
};

// How a ball is written as text (scalar_text.hpp): its midpoint; its lower or upper bound rounded
// outward; or its certified digits (those every point of the ball shares, with the radius when they are
// fewer than asked).
enum class BallText { midpoint, lower, upper, certified };
inline thread_local BallText ball_text = BallText::midpoint;

class Ball {
 public:
  static constexpr bool records_decisions = true;

  Ball() { arb_init(x_); }
  template <typename I, std::enable_if_t<std::is_integral_v<I>, int> = 0>
  Ball(I v) {  // NOLINT: integers convert exactly, as the mechanics' Scalar(2) expects
    arb_init(x_);
    if constexpr (std::is_unsigned_v<I>) arb_set_ui(x_, static_cast<ulong>(v));
    else arb_set_si(x_, static_cast<slong>(v));
  }
  Ball(double v) {  // NOLINT: exact (the double's own value)
    arb_init(x_);
    arb_set_d(x_, v);
  }
  // A decimal as written: exact where it is a binary fraction at the working precision, else a tight
  // ball around it. Throws std::invalid_argument for text Arb does not read.
  explicit Ball(const std::string& decimal);
  explicit Ball(const char* decimal) : Ball(std::string(decimal)) {}
  Ball(const Ball& o) {
    arb_init(x_);
    arb_set(x_, o.x_);
  }
  Ball(Ball&& o) noexcept {
    arb_init(x_);
    arb_swap(x_, o.x_);
  }
  Ball& operator=(const Ball& o) {
    arb_set(x_, o.x_);
    return *this;
  }
  Ball& operator=(Ball&& o) noexcept {
    arb_swap(x_, o.x_);
    return *this;
  }
  ~Ball() { arb_clear(x_); }

  arb_ptr get() { return x_; }
  arb_srcptr get() const { return x_; }

  Ball& operator+=(const Ball& o) {
    arb_add(x_, x_, o.x_, ball_bits);
    return *this;
  }
  Ball& operator-=(const Ball& o) {
    arb_sub(x_, x_, o.x_, ball_bits);
    return *this;
  }
  Ball& operator*=(const Ball& o) {
    arb_mul(x_, x_, o.x_, ball_bits);
    return *this;
  }
  Ball& operator/=(const Ball& o) {
    arb_div(x_, x_, o.x_, ball_bits);
    return *this;
  }
  Ball operator-() const {
    Ball r;
    arb_neg(r.x_, x_);
    return r;
  }
  Ball operator+() const { return *this; }

  // The midpoint, rounded to nearest.
  explicit operator double() const { return arf_get_d(arb_midref(x_), ARF_RND_NEAR); }
  // A double at least every point of the ball (+inf where it is not finite).
  double upper_double() const;
  explicit operator long double() const { return static_cast<double>(*this); }

  bool exact() const { return arb_is_exact(x_); }
  bool finite() const { return arb_is_finite(x_); }
  bool contains_zero() const { return arb_contains_zero(x_); }
  bool exactly_zero() const { return arb_is_zero(x_); }
  // The radius, rounded up; the midpoint; the bounds, each as a ball holding one exact number.
  Ball radius() const;
  Ball midpoint() const;
  Ball lower() const;
  Ball upper() const;

  static Ball pi();
  // [lo, hi] of two exact numbers, or the smallest ball holding both balls.
  static Ball hull(const Ball& a, const Ball& b);

  // Text in the thread's BallText form with `digits` significant digits (the working precision's when
  // digits exceeds it); "nan" for a ball that is not finite.
  void append_text(std::string& out, int digits) const;

  // The significant decimal digits the working precision holds.
  static int precision_digits();

 private:
  arb_t x_;
};

Ball operator+(const Ball& a, const Ball& b);
Ball operator-(const Ball& a, const Ball& b);
Ball operator*(const Ball& a, const Ball& b);
Ball operator/(const Ball& a, const Ball& b);

// a < b (strict) or a <= b, as the header says.
bool ball_less(const Ball& a, const Ball& b, bool strict);
// |x| <= tol as a decision: undecided where the ball of tol - |x| holds 0, and then true (the zero
// branch) when x's ball holds 0, the exact value being possibly zero (rounding.hpp, within_rounding).
bool ball_within(const Ball& x, const Ball& tol);
inline bool operator<(const Ball& a, const Ball& b) { return ball_less(a, b, true); }
inline bool operator<=(const Ball& a, const Ball& b) { return ball_less(a, b, false); }
inline bool operator>(const Ball& a, const Ball& b) { return ball_less(b, a, true); }
inline bool operator>=(const Ball& a, const Ball& b) { return ball_less(b, a, false); }
inline bool operator==(const Ball& a, const Ball& b) { return a.exact() && arb_equal(a.get(), b.get()); }
inline bool operator!=(const Ball& a, const Ball& b) { return !(a == b); }

Ball abs(const Ball& x);
Ball sqrt(const Ball& x);
Ball hypot(const Ball& a, const Ball& b);
Ball sin(const Ball& x);
Ball cos(const Ball& x);
Ball atan2(const Ball& y, const Ball& x);
Ball acos(const Ball& x);
Ball floor(const Ball& x);
inline Ball fabs(const Ball& x) { return abs(x); }
inline Ball abs2(const Ball& x) {
  Ball r;
  arb_sqr(r.get(), x.get(), ball_bits);
  return r;
}
inline bool isfinite(const Ball& x) { return x.finite(); }
inline bool isinf(const Ball& x) { return !x.finite() && !arf_is_nan(arb_midref(x.get())); }
inline bool isnan(const Ball& x) { return arf_is_nan(arb_midref(x.get())); }

template <>
struct SinCosRadians<Ball> {
  static void of(const Ball& rad, Ball& s, Ball& c) { arb_sin_cos(s.get(), c.get(), rad.get(), ball_bits); }
};

// The enclosure's own answers where the rounding model (rounding.hpp) would estimate: the condition of
// a symmetric positive definite 3x3 matrix, enclosed.
template <>
struct EnclosureTraits<Ball> {
  static constexpr bool is_enclosure = true;
  static Ball spd_condition(const Mat3<Ball>& M);
  static long bits() { return ball_bits; }
  static bool within(const Ball& x, const Ball& tol) { return ball_within(x, tol); }
  static bool identical(const Ball& a, const Ball& b) { return arb_equal(a.get(), b.get()) != 0; }
};

}  // namespace impact3d

namespace std {
template <>
class numeric_limits<impact3d::Ball> {
 public:
  static constexpr bool is_specialized = true;
  static constexpr bool is_signed = true;
  static constexpr bool is_integer = false;
  static constexpr bool is_exact = false;
  static constexpr bool has_infinity = true;
  static constexpr bool has_quiet_NaN = true;
  static constexpr int radix = 2;
  // Not a fixed count: the working precision decides (Ball::precision_digits); this asks for all of them.
  static constexpr int digits10 = 1000;
  static constexpr int max_digits10 = 1000;
  static impact3d::Ball epsilon() {
    impact3d::Ball e(1);
    arb_mul_2exp_si(e.get(), e.get(), 1 - impact3d::ball_bits);
    return e;
  }
  static impact3d::Ball infinity() {
    impact3d::Ball x;
    arb_pos_inf(x.get());
    return x;
  }
  static impact3d::Ball quiet_NaN() {
    impact3d::Ball x;
    arb_indeterminate(x.get());
    return x;
  }
  static impact3d::Ball max() { return infinity(); }
  static impact3d::Ball lowest() { return -infinity(); }
};
}  // namespace std

namespace Eigen {
namespace internal {
// |x|^2 of a ball holding zero is [0, r^2], not the [-r^2, r^2] of x * x: norms stay enclosures with a
// root.
template <>
struct abs2_impl<impact3d::Ball> {
  static impact3d::Ball run(const impact3d::Ball& x) {
    impact3d::Ball r;
    arb_sqr(r.get(), x.get(), impact3d::ball_bits);
    return r;
  }
};
}  // namespace internal

template <>
struct NumTraits<impact3d::Ball> : GenericNumTraits<impact3d::Ball> {
  using Real = impact3d::Ball;
  using NonInteger = impact3d::Ball;
  using Literal = impact3d::Ball;
  using Nested = impact3d::Ball;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1, ReadCost = 1, AddCost = 8, MulCost = 16 };
  static Real epsilon() { return std::numeric_limits<Real>::epsilon(); }
  static Real dummy_precision() { return Real(1000) * epsilon(); }
  static Real highest() { return std::numeric_limits<Real>::max(); }
  static Real lowest() { return std::numeric_limits<Real>::lowest(); }
  static Real infinity() { return std::numeric_limits<Real>::infinity(); }
  static Real quiet_NaN() { return std::numeric_limits<Real>::quiet_NaN(); }
  static int digits10() { return impact3d::Ball::precision_digits(); }
};
}  // namespace Eigen
