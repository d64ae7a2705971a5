// Exact rational arithmetic (Boost cpp_rational). A collision whose rotations are rational (angles at
// multiples of 90 degrees, orientations given as rational matrices, unit contact vectors with rational
// components) has a rational K, Full Impact and Brach impulse; a square root is exact when its radicand
// is the square of a rational, and otherwise the computation stops and says which quantity needs it.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/LU>
#include <boost/multiprecision/cpp_int.hpp>

// Boost 1.74's cpp_int checks whether a type it might convert from is a byte container by reading
// iterator_traits<T::const_iterator>; Eigen 3.4 gives non-vector expressions const_iterator = void,
// which makes that check a hard error. Eigen's dense expressions are never byte containers.
namespace boost::multiprecision::detail {
template <class X, int R, int C, bool I>
struct is_byte_container<Eigen::Block<X, R, C, I>> : boost::false_type {};
template <class S, int R, int C, int O, int MR, int MC>
struct is_byte_container<Eigen::Matrix<S, R, C, O, MR, MC>> : boost::false_type {};
template <class F, class L, class R>
struct is_byte_container<Eigen::CwiseBinaryOp<F, L, R>> : boost::false_type {};
template <class F, class X>
struct is_byte_container<Eigen::CwiseUnaryOp<F, X>> : boost::false_type {};
template <class F, class X>
struct is_byte_container<Eigen::CwiseNullaryOp<F, X>> : boost::false_type {};
template <class L, class R, int O>
struct is_byte_container<Eigen::Product<L, R, O>> : boost::false_type {};
template <class X>
struct is_byte_container<Eigen::Transpose<X>> : boost::false_type {};
template <class D, class R>
struct is_byte_container<Eigen::Solve<D, R>> : boost::false_type {};
template <class X>
struct is_byte_container<Eigen::Inverse<X>> : boost::false_type {};
template <class X, int I>
struct is_byte_container<Eigen::Diagonal<X, I>> : boost::false_type {};
template <class X>
struct is_byte_container<Eigen::DiagonalWrapper<X>> : boost::false_type {};
template <class X, int O, class S>
struct is_byte_container<Eigen::Map<X, O, S>> : boost::false_type {};
}  // namespace boost::multiprecision::detail

namespace impact3d {

// Expression templates off, as for the floating types: Eigen must only ever see the number type.
using rational = boost::multiprecision::number<boost::multiprecision::rational_adaptor<boost::multiprecision::cpp_int_backend<>>,
                                               boost::multiprecision::et_off>;

template <typename Scalar>
inline constexpr bool is_exact_v = std::numeric_limits<Scalar>::is_exact;

// isfinite for every scalar type: exact types have no infinities (their division by zero throws).
template <typename Scalar>
bool is_finite(const Scalar& x) {
  if constexpr (std::numeric_limits<Scalar>::is_exact) {
    return true;
  } else {
    using std::isfinite;
    return isfinite(x);
  }
}

// Every entry of an Eigen vector or matrix finite.
template <typename Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& m) {
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (!is_finite(m(i, j))) return false;
  return true;
}

// The largest integer <= x, for every scalar type.
template <typename Scalar>
Scalar floor_of(const Scalar& x) {
  if constexpr (std::numeric_limits<Scalar>::is_exact) {
    using boost::multiprecision::cpp_int;
    const cpp_int n = boost::multiprecision::numerator(x), d = boost::multiprecision::denominator(x);
    cpp_int q = n / d;  // truncates towards zero
    if (q * d != n && n < 0) q -= 1;
    return Scalar(q);
  } else {
    using std::floor;
    return floor(x);
  }
}

// A fraction in a floating type, numerator and denominator each read exactly (to the type's precision).
template <typename Float>
Float to_floating(const rational& q) {
  return Float(boost::multiprecision::numerator(q).str()) / Float(boost::multiprecision::denominator(q).str());
}

// A quantity of an exact computation that is not rational.
struct Irrational : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// sqrt(q) when q is the square of a rational; otherwise Irrational naming `what`.
inline rational exact_sqrt(const rational& q, const std::string& what) {
  using boost::multiprecision::cpp_int;
  if (q < 0) throw Irrational(what + ": square root of a negative number");
  const cpp_int n = boost::multiprecision::numerator(q), d = boost::multiprecision::denominator(q);
  const cpp_int rn = boost::multiprecision::sqrt(n), rd = boost::multiprecision::sqrt(d);
  if (rn * rn != n || rd * rd != d) throw Irrational(what + " needs a square root");
  return rational(rational(rn) / rational(rd));
}

}  // namespace impact3d

namespace Eigen {
template <>
struct NumTraits<impact3d::rational> : GenericNumTraits<impact3d::rational> {
  using Real = impact3d::rational;
  using NonInteger = impact3d::rational;
  using Literal = impact3d::rational;
  using Nested = impact3d::rational;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1, ReadCost = 1, AddCost = 8, MulCost = 16 };
  static Real epsilon() { return 0; }
  static Real dummy_precision() { return 0; }
  static Real highest() { return 0; }
  static Real lowest() { return 0; }
  static Real infinity() { return 0; }
  static Real quiet_NaN() { return 0; }
  static int digits10() { return 0; }
};
}  // namespace Eigen
