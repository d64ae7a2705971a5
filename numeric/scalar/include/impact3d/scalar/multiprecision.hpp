// The wider scalar types impact3d is verified at, and their Eigen traits. Expression templates are off so
// that Eigen never sees a Boost expression type; Boost's own Eigen adapter (1.74) lacks infinity() and
// quiet_NaN(), which Eigen 3.4's hypot needs, so the traits are defined here on GenericNumTraits, whose
// members come from std::numeric_limits (specialized by Boost for these types).
#pragma once

#include <limits>

#include <Eigen/Core>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include "impact3d/scalar/fixed_float.hpp"
#include "impact3d/scalar/lean_twin.hpp"
#include "impact3d/scalar/sin_cos_radians.hpp"

namespace impact3d::mp {

using float128 = boost::multiprecision::float128;
using float50 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>, boost::multiprecision::et_off>;
// The MPFR number holds its limbs in the object (allocate_stack): no allocation per operation or
// temporary, which at 100 digits was a third of the time.
using float100 = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<100, boost::multiprecision::allocate_stack>,
                                               boost::multiprecision::et_off>;

// std::numeric_limits of these numbers, which Boost 1.74 fills on first use and two threads could race
// on, are filled at start-up by the one object that defines limits_filled (scalar/src/thread_caches.cpp,
// which says why). Every object that includes this header keeps a reference to it, so that every
// program using these numbers links that object and its fill, while no other object compiles the fill.
extern const bool limits_filled;
[[gnu::used]] static const bool* const limits_anchor = &limits_filled;

template <typename T>
struct NumTraitsFor : Eigen::GenericNumTraits<T> {
  using Real = T;
  using NonInteger = T;
  using Literal = T;
  using Nested = T;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 4,
    MulCost = 8
  };
  static T epsilon() { return std::numeric_limits<T>::epsilon(); }
  // Eigen's trait: the default tolerance of its isApprox and isZero. Not a bound of impact3d's (those are
  // rounding.hpp's): impact3d calls isZero only on exact types, whose trait is exact.hpp's 0.
  static T dummy_precision() { return T(1000) * std::numeric_limits<T>::epsilon(); }
  static T highest() { return (std::numeric_limits<T>::max)(); }
  static T lowest() { return std::numeric_limits<T>::lowest(); }
  static T infinity() { return std::numeric_limits<T>::infinity(); }
  static T quiet_NaN() { return std::numeric_limits<T>::quiet_NaN(); }
  static int digits10() { return std::numeric_limits<T>::digits10; }
};

}  // namespace impact3d::mp

// Boost 1.74's three-operand MPFR operations take their last operand only as the dynamic backend, so
// for the stack backend a * b fell back to a copy of a and then a *= b (1 to 4% of the 100-digit lean
// route, BENCHMARKS.md). These write the result in one correctly rounded MPFR call, the value the copy
// and the in-place operation gave; Boost's fallback differs only in the sign of an exact zero from
// y - y into y itself, which no operator of a number without expression templates does (each writes
// a fresh result).
namespace boost::multiprecision::backends {

template <unsigned D>
inline void eval_add(mpfr_float_backend<D, allocate_stack>& r, const mpfr_float_backend<D, allocate_stack>& x,
                     const mpfr_float_backend<D, allocate_stack>& y) {
  mpfr_add(r.data(), x.data(), y.data(), MPFR_RNDN);
}
template <unsigned D>
inline void eval_subtract(mpfr_float_backend<D, allocate_stack>& r, const mpfr_float_backend<D, allocate_stack>& x,
                          const mpfr_float_backend<D, allocate_stack>& y) {
  mpfr_sub(r.data(), x.data(), y.data(), MPFR_RNDN);
}
template <unsigned D>
inline void eval_multiply(mpfr_float_backend<D, allocate_stack>& r, const mpfr_float_backend<D, allocate_stack>& x,
                          const mpfr_float_backend<D, allocate_stack>& y) {
  if (&x == &y)
    mpfr_sqr(r.data(), x.data(), MPFR_RNDN);
  else
    mpfr_mul(r.data(), x.data(), y.data(), MPFR_RNDN);
}
template <unsigned D>
inline void eval_divide(mpfr_float_backend<D, allocate_stack>& r, const mpfr_float_backend<D, allocate_stack>& x,
                        const mpfr_float_backend<D, allocate_stack>& y) {
  mpfr_div(r.data(), x.data(), y.data(), MPFR_RNDN);
}

}  // namespace boost::multiprecision::backends

namespace impact3d {

namespace mp {
// The sine and cosine of x, each correctly rounded to nearest at its own precision (s and c alike), the
// values mpfr_sin_cos gives, which Boost's sin and cos (mpfr_sin, mpfr_cos) give too (mpfr_sin_cos.cpp).
void sin_cos(mpfr_ptr s, mpfr_ptr c, mpfr_srcptr x);
}  // namespace mp

template <>
struct SinCosRadians<mp::float100> {
  static void of(const mp::float100& rad, mp::float100& s, mp::float100& c) {
    mp::sin_cos(s.backend().data(), c.backend().data(), rad.backend().data());
  }
};

namespace mp {
// MPFR's 100 digits, computed faster by FixedFloat: the same precision, the same value of every
// operation the lean route takes (check_fixed_float). Boost rounds 100 digits up to 334 bits.
using float100_twin = FixedFloat<334>;
static_assert(std::numeric_limits<float100>::digits == 334);
}  // namespace mp

template <int P>
struct SinCosRadians<mp::FixedFloat<P>> {
  static void of(const mp::FixedFloat<P>& rad, mp::FixedFloat<P>& s, mp::FixedFloat<P>& c) {
    using F = mp::FixedFloat<P>;
    F sine, cosine;  // fresh: rad may be s or c
    typename F::View vr(rad), vs(sine), vc(cosine);
    mp::sin_cos(vs.x, vc.x, vr.x);
    sine.take(vs), cosine.take(vc);
    s = sine, c = cosine;
  }
};

template <>
struct LeanTwin<mp::float100> {
  using type = mp::float100_twin;
  static type to(const mp::float100& x) { return type::of(x.backend().data()); }
  static mp::float100 from(const type& x) {
    mp::float100 out;
    x.to(out.backend().data());
    return out;
  }
};

}  // namespace impact3d

namespace Eigen {
template <>
struct NumTraits<impact3d::mp::float128> : impact3d::mp::NumTraitsFor<impact3d::mp::float128> {};
template <>
struct NumTraits<impact3d::mp::float50> : impact3d::mp::NumTraitsFor<impact3d::mp::float50> {};
template <>
struct NumTraits<impact3d::mp::float100> : impact3d::mp::NumTraitsFor<impact3d::mp::float100> {};
template <int P>
struct NumTraits<impact3d::mp::FixedFloat<P>> : impact3d::mp::NumTraitsFor<impact3d::mp::FixedFloat<P>> {};
}  // namespace Eigen
