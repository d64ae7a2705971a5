// Forward-mode derivatives through the same templated mechanics (issue 12's sensitivities): Dual is
// Eigen's AutoDiffScalar over a fixed-size vector of doubles, one entry per input differentiated, so a
// case with more inputs is differentiated kDualWidth inputs at a time. Fixed, not dynamic: a constant
// (Scalar(2), pi) then carries zero derivatives of the full width, where a dynamic one carries none and
// Eigen's operators meet vectors of different lengths inside unevaluated expressions (an assertion, or
// a read out of bounds without one). Comparisons use the value, so every branch (regime, cap, sign) is
// the one the value takes: the derivative is the regime-fixed one. What Eigen does not define for it is
// defined here, in namespace Eigen for ADL.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/AutoDiff>

#include "impact3d/scalar/planar_norm.hpp"
#include "impact3d/scalar/types.hpp"

namespace impact3d {

inline constexpr int kDualWidth = 16;
using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, kDualWidth, 1>>;

template <>
struct DualTraits<Dual> {
  static constexpr bool is_dual = true;
  using Value = double;
  static const double& value(const Dual& x) { return x.value(); }
};

}  // namespace impact3d

namespace Eigen {

// sqrt(a^2 + b^2) without overflow, its value the double path's (planar_norm). At a = b = 0 it has no
// derivative unless neither moves: NaN there.
inline impact3d::Dual hypot(const impact3d::Dual& a, const impact3d::Dual& b) {
  using D = impact3d::Dual::DerType;
  const double h = impact3d::planar_norm(a.value(), b.value());
  if (h > 0) return impact3d::Dual(h, D((a.value() / h) * a.derivatives() + (b.value() / h) * b.derivatives()));
  if (a.derivatives().isZero(0) && b.derivatives().isZero(0)) return impact3d::Dual(h, D::Zero());
  return impact3d::Dual(h, D::Constant(std::numeric_limits<double>::quiet_NaN()));
}

// A step function: derivative zero.
inline impact3d::Dual floor(const impact3d::Dual& x) {
  return impact3d::Dual(std::floor(x.value()), impact3d::Dual::DerType::Zero());
}

inline bool isfinite(const impact3d::Dual& x) { return std::isfinite(x.value()); }
inline bool isnan(const impact3d::Dual& x) { return std::isnan(x.value()); }
inline bool isinf(const impact3d::Dual& x) { return std::isinf(x.value()); }

}  // namespace Eigen
