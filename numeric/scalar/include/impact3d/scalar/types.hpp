// Fixed-size Eigen types and exact constants shared by every algorithm of impact3d::numeric.
#pragma once

#include <algorithm>
#include <limits>
#include <optional>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/LU>
#include <boost/math/constants/constants.hpp>

namespace impact3d {

template <typename Scalar>
using Vec3 = Eigen::Matrix<Scalar, 3, 1>;
template <typename Scalar>
using Mat3 = Eigen::Matrix<Scalar, 3, 3>;

// A rational constant built in the target type, so that no constant is rounded through double on a
// long double or multiprecision path.
template <typename Scalar>
Scalar ratio(long long p, long long q) {
  return Scalar(p) / Scalar(q);
}

// A scalar that carries first derivatives beside its value (scalar/autodiff.hpp specializes this for
// its dual type): decisions and rounding bounds use the value alone, so the branch taken is the value's.
template <typename Scalar>
struct DualTraits {
  static constexpr bool is_dual = false;
  using Value = Scalar;
  static const Scalar& value(const Scalar& x) { return x; }
};
template <typename Scalar>
inline constexpr bool is_dual_v = DualTraits<Scalar>::is_dual;

// A scalar that encloses its exact value (scalar/ball.hpp specializes this): where the rounding model
// (rounding.hpp) estimates, the enclosure answers for itself.
template <typename Scalar>
struct EnclosureTraits {
  static constexpr bool is_enclosure = false;
};
template <typename Scalar>
inline constexpr bool is_enclosure_v = EnclosureTraits<Scalar>::is_enclosure;

template <typename Scalar>
Scalar pi() {
  static_assert(!std::numeric_limits<Scalar>::is_exact, "pi has no exact value");
  if constexpr (is_dual_v<Scalar>) return Scalar(pi<typename DualTraits<Scalar>::Value>());
  else if constexpr (requires { Scalar::pi(); }) return Scalar::pi();
  else return boost::math::constants::pi<Scalar>();
}

// A scalar as a double, for messages and the rounding model's comparisons with double thresholds.
template <typename Scalar>
double to_double(const Scalar& x) {
  return static_cast<double>(DualTraits<Scalar>::value(x));
}

template <typename Scalar>
Scalar degrees(const Scalar& rad) {
  return rad * Scalar(180) / pi<Scalar>();
}

// Unit vectors of a solution plane at angle phi from t towards z: u in the plane, w normal to it.
template <typename Scalar>
struct PlaneAxes {
  Scalar c, s;  // cos phi, sin phi
  Vec3<Scalar> u() const { return Vec3<Scalar>(Scalar(0), c, s); }
  Vec3<Scalar> w() const { return Vec3<Scalar>(Scalar(0), -s, c); }
};

// X = A^-1 B for a dual scalar (fixed-width derivatives, autodiff.hpp): the values by `factor` (a
// factorization of A's values, or nothing where A is singular), the derivatives by the same
// factorization, dX = A^-1 (dB - dA X). Eigen's triangular solves skip a right-hand side whose value is
// zero, and with it that entry's derivatives.
template <typename Scalar, int Cols, typename Factor>
std::optional<Eigen::Matrix<Scalar, 3, Cols>> dual_solve(const Mat3<Scalar>& A, const Eigen::Matrix<Scalar, 3, Cols>& B,
                                                          Factor&& factor) {
  using V = typename DualTraits<Scalar>::Value;
  using D = typename Scalar::DerType;
  Mat3<V> Av;
  Eigen::Matrix<V, 3, Cols> Bv;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) Av(i, j) = A(i, j).value();
    for (int j = 0; j < Cols; ++j) Bv(i, j) = B(i, j).value();
  }
  const auto f = factor(Av);
  if (!f) return std::nullopt;
  const Eigen::Matrix<V, 3, Cols> X = f->solve(Bv);
  Eigen::Matrix<Scalar, 3, Cols> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < Cols; ++j) out(i, j) = Scalar(X(i, j), D::Zero());
  for (Eigen::Index k = 0; k < D::RowsAtCompileTime; ++k) {
    Eigen::Matrix<V, 3, Cols> R;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < Cols; ++j) {
        V r = B(i, j).derivatives()[k];
        for (int m = 0; m < 3; ++m) r -= A(i, m).derivatives()[k] * X(m, j);
        R(i, j) = r;
      }
    const Eigen::Matrix<V, 3, Cols> dX = f->solve(R);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < Cols; ++j) out(i, j).derivatives()[k] = dX(i, j);
  }
  return out;
}

// A^-1 B in ball arithmetic (an enclosure type): elimination encloses the solution whichever pivots it
// takes, and takes the largest midpoints without a comparison of balls (none to decide, so none to
// record). Empty where a pivot's ball holds zero: singular as far as the enclosure can tell.
template <typename Scalar, int Cols>
std::optional<Eigen::Matrix<Scalar, 3, Cols>> enclosure_solve(Mat3<Scalar> A, Eigen::Matrix<Scalar, 3, Cols> B) {
  using std::abs;
  for (int k = 0; k < 3; ++k) {
    int pivot = k;
    for (int i = k + 1; i < 3; ++i)
      if (static_cast<double>(abs(A(i, k))) > static_cast<double>(abs(A(pivot, k)))) pivot = i;
    if (A(pivot, k).contains_zero()) return std::nullopt;
    A.row(k).swap(A.row(pivot));
    B.row(k).swap(B.row(pivot));
    for (int i = k + 1; i < 3; ++i) {
      const Scalar f = A(i, k) / A(k, k);
      for (int j = k; j < 3; ++j) A(i, j) -= f * A(k, j);
      for (int j = 0; j < Cols; ++j) B(i, j) -= f * B(k, j);
    }
  }
  Eigen::Matrix<Scalar, 3, Cols> X;
  for (int c = 0; c < Cols; ++c)
    for (int k = 2; k >= 0; --k) {
      Scalar r = B(k, c);
      for (int j = k + 1; j < 3; ++j) r -= A(k, j) * X(j, c);
      X(k, c) = r / A(k, k);
    }
  return X;
}

// x = J^-1 b for a symmetric positive definite J: Cholesky for floating types, LU for exact ones, ball
// elimination for enclosures (NaN where J's balls hold a singular matrix).
template <typename Scalar, typename Rhs>
auto spd_solve(const Eigen::Matrix<Scalar, 3, 3>& J, const Rhs& b) {
  if constexpr (std::numeric_limits<Scalar>::is_exact) {
    return J.fullPivLu().solve(b).eval();
  } else if constexpr (is_enclosure_v<Scalar>) {
    using M = Eigen::Matrix<Scalar, 3, Rhs::ColsAtCompileTime>;
    const auto X = enclosure_solve<Scalar, Rhs::ColsAtCompileTime>(J, M(b));
    return X ? *X : M::Constant(std::numeric_limits<Scalar>::quiet_NaN());
  } else if constexpr (is_dual_v<Scalar>) {
    using V = typename DualTraits<Scalar>::Value;
    const Eigen::Matrix<Scalar, 3, Rhs::ColsAtCompileTime> B = b;
    return *dual_solve(J, B, [](const Mat3<V>& M) { return std::optional<Eigen::LLT<Mat3<V>>>(M.llt()); });
  } else {
    return J.llt().solve(b).eval();
  }
}

// [r]x: the matrix with skew(r) * p == r x p.
template <typename Scalar>
Mat3<Scalar> skew(const Vec3<Scalar>& r) {
  Mat3<Scalar> s;
  s << Scalar(0), -r.z(), r.y(),  //
      r.z(), Scalar(0), -r.x(),   //
      -r.y(), r.x(), Scalar(0);
  return s;
}

}  // namespace impact3d
