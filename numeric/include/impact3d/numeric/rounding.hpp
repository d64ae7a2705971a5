// The rounding model: how far a result computed at a precision with unit roundoff eps can stray from the
// exact result of the same decimal inputs, and the warnings a result gets when that bound is not small.
//
// Relative error of an impulse <= kResultRoundings * eps * A, with the amplification
//   A = kappa(K) * cond(J) * max(1, (|v_IC1| + |v_IC2|) / V_rn):
//   - kappa(K): every impulse is a 3x3 solve with K (or its closed form);
//   - cond(J): K holds J^-1, formed from the inertia tensors (the worse of the two vehicles);
//   - (|v_IC1| + |v_IC2|) / V_rn: the decimal inputs and rotations are rounded to the type, so V_rn =
//     n.(v2 - v1) carries an absolute error of eps times the point speeds, and every impulse is
//     proportional to V_rn through the restitution constraint (a grazing contact is ill-posed).
// kResultRoundings = 32 covers the handful of roundings on each path that do not cancel; it is the bound
// `impact3d verify` checks every precision against (100-digit reference) and the engines against
// each other. A ratio carries its quotient's factor (1 + |V_cp / V_n|)(1 + |mu|) besides.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Eigenvalues>

#include "impact3d/numeric/exact.hpp"
#include "impact3d/numeric/kinematics.hpp"
#include "impact3d/numeric/scalars.hpp"

namespace impact3d::rounding {

inline constexpr double kResultRoundings = 32;
// A result is trusted when its bound is at most this fraction of it: six significant digits, more than
// any input of a reconstruction carries. Beyond it the result is flagged and a precision suggested.
inline constexpr double kTrustedFraction = 1e-6;

// 2-norm condition of a symmetric matrix that should be positive definite; infinity when rounding made
// it indefinite or singular (the computation at this precision cannot be trusted at all).
template <typename Scalar>
Scalar spd_condition(const Mat3<Scalar>& M) {
  if constexpr (is_exact_v<Scalar>) {
    return Scalar(1);
  } else {
    Eigen::SelfAdjointEigenSolver<Mat3<Scalar>> eig(M, Eigen::EigenvaluesOnly);
    const Scalar lo = eig.eigenvalues().minCoeff(), hi = eig.eigenvalues().maxCoeff();
    if (!(lo > Scalar(0)) || !is_finite(hi)) return std::numeric_limits<Scalar>::infinity();
    return hi / lo;
  }
}

// The amplification A above; exact arithmetic has nothing to amplify.
template <typename Scalar>
Scalar amplification(const Scene<Scalar>& s, const Scalar& kappa_K) {
  if constexpr (is_exact_v<Scalar>) {
    return Scalar(1);
  } else {
    using std::max;
    const Scalar cond_J = max(spd_condition(s.body[0].J_B), spd_condition(s.body[1].J_B));
    const Scalar V_rn = relative_velocity_C(s).x();
    const Scalar cancellation = max(Scalar(1), Scalar((v_Ic_W(s.body[0]).norm() + v_Ic_W(s.body[1]).norm()) / V_rn));
    const Scalar a = kappa_K * cond_J * cancellation;
    return is_finite(a) && a > Scalar(0) ? a : std::numeric_limits<Scalar>::infinity();
  }
}

// The quotient's factor of a ratio u.P / P_n, 1 + |V_cp / V_n|: ratios and the decisions taken on them
// carry it besides the amplification.
template <typename Scalar>
Scalar quotient_factor(const Vec3<Scalar>& V_ri) {
  using std::hypot;
  return Scalar(1) + hypot(V_ri.y(), V_ri.z()) / V_ri.x();
}

// The relative bound of an impulse at this precision.
template <typename Scalar>
Scalar relative_bound(const Scalar& amplification) {
  if constexpr (is_exact_v<Scalar>) return Scalar(0);
  else return Scalar(kResultRoundings) * std::numeric_limits<Scalar>::epsilon() * amplification;
}

// The narrowest precision whose bound for `amplification` is within the trusted fraction; empty when
// none is (or the amplification is not finite, as when K or J is not positive definite here).
inline std::string precision_for(double amplification) {
  if (!std::isfinite(amplification)) return "";
  for (const auto& p : kPrecisions)
    if (kResultRoundings * p.unit_roundoff * amplification <= kTrustedFraction) return std::string(p.name);
  return "";
}

}  // namespace impact3d::rounding
