// The type the lean path (lean.hpp, raw_collision.hpp) computes a scalar's results in: the scalar itself,
// or a twin whose every operation gives the same value bit for bit, only faster. multiprecision.hpp pairs
// MPFR's 100 digits with FixedFloat<334> (fixed_float.hpp); tests/mechanics/check_fixed_float.cpp holds each
// operation, and the lean route as a whole, to MPFR's.
#pragma once

#include <type_traits>

#include <Eigen/Core>

namespace impact3d {

template <typename Scalar>
struct LeanTwin {
  using type = Scalar;
  static const Scalar& to(const Scalar& x) { return x; }
  static const Scalar& from(const Scalar& x) { return x; }
};
template <typename Scalar>
using lean_twin_t = typename LeanTwin<Scalar>::type;
template <typename Scalar>
inline constexpr bool has_lean_twin_v = !std::is_same_v<lean_twin_t<Scalar>, Scalar>;

// Each number of a matrix or vector by f.
template <typename To, typename F, typename Derived>
Eigen::Matrix<To, Derived::RowsAtCompileTime, Derived::ColsAtCompileTime> convert_each(const Eigen::MatrixBase<Derived>& m, F&& f) {
  Eigen::Matrix<To, Derived::RowsAtCompileTime, Derived::ColsAtCompileTime> out;
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) out(i, j) = f(m(i, j));
  return out;
}

}  // namespace impact3d
