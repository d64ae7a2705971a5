// Fixed-size Eigen types and exact constants shared by every algorithm of impact3d::numeric.
#pragma once

#include <limits>

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

template <typename Scalar>
Scalar pi() {
  static_assert(!std::numeric_limits<Scalar>::is_exact, "pi has no exact value");
  return boost::math::constants::pi<Scalar>();
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

// x = J^-1 b for a symmetric positive definite J: Cholesky for floating types, LU for exact ones.
template <typename Scalar, typename Rhs>
auto spd_solve(const Eigen::Matrix<Scalar, 3, 3>& J, const Rhs& b) {
  if constexpr (std::numeric_limits<Scalar>::is_exact) return J.fullPivLu().solve(b).eval();
  else return J.llt().solve(b).eval();
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
