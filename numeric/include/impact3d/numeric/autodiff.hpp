// Forward-mode derivatives through the same templated mechanics (issue 12's sensitivities): Dual is
// Eigen's AutoDiffScalar over a vector of doubles, one entry per input differentiated. Comparisons use
// the value, so every branch (regime, cap, sign) is the one the value takes: the derivative is the
// regime-fixed one. What Eigen does not define for it is defined here, in namespace Eigen for ADL.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/AutoDiff>

#include "impact3d/numeric/types.hpp"

namespace impact3d {

using Dual = Eigen::AutoDiffScalar<Eigen::VectorXd>;

template <>
struct DualTraits<Dual> {
  static constexpr bool is_dual = true;
  using Value = double;
  static const double& value(const Dual& x) { return x.value(); }
};

}  // namespace impact3d

namespace Eigen {

// sqrt(a^2 + b^2) without overflow. At a = b = 0 it has no derivative unless neither moves: NaN there.
inline impact3d::Dual hypot(const impact3d::Dual& a, const impact3d::Dual& b) {
  const double h = std::hypot(a.value(), b.value());
  const Index n = std::max(a.derivatives().size(), b.derivatives().size());
  const VectorXd da = a.derivatives().size() ? a.derivatives() : VectorXd::Zero(n);
  const VectorXd db = b.derivatives().size() ? b.derivatives() : VectorXd::Zero(n);
  if (h > 0) return impact3d::Dual(h, (a.value() / h) * da + (b.value() / h) * db);
  if (da.isZero(0) && db.isZero(0)) return impact3d::Dual(h, VectorXd::Zero(n));
  return impact3d::Dual(h, VectorXd::Constant(n, std::numeric_limits<double>::quiet_NaN()));
}

// A step function: derivative zero.
inline impact3d::Dual floor(const impact3d::Dual& x) {
  return impact3d::Dual(std::floor(x.value()), VectorXd::Zero(x.derivatives().size()));
}

inline bool isfinite(const impact3d::Dual& x) { return std::isfinite(x.value()); }
inline bool isnan(const impact3d::Dual& x) { return std::isnan(x.value()); }
inline bool isinf(const impact3d::Dual& x) { return std::isinf(x.value()); }

}  // namespace Eigen
