// Every strategy is three linear constraints on P = (P_n, P_t, P_z). The direct engine writes them as
// rows c . P = rhs and solves the 3x3 system; the closed forms of the paper are never used here, so
// this engine is an independent reference for them.
#pragma once

#include <array>
#include <optional>

#include <Eigen/LU>

#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/strategy.hpp"

namespace impact3d::direct {

template <typename Scalar>
struct Row {
  Vec3<Scalar> c;
  Scalar rhs;
};

// The post-impact relative velocity along unit u takes the value target: u^T K P = m' (u.V_ri - target).
template <typename Scalar>
Row<Scalar> velocity_row(const Problem<Scalar>& p, const Vec3<Scalar>& u, const Scalar& target) {
  return {p.K.transpose() * u, p.m_prime * (u.dot(p.V_ri) - target)};
}

// Poisson/kinetic restitution on the normal: V_rnf = -eps V_rni (the first of eqs 9, 17, 23).
template <typename Scalar>
Row<Scalar> restitution_row(const Problem<Scalar>& p, const Scalar& eps) {
  return velocity_row(p, Vec3<Scalar>(Vec3<Scalar>::UnitX()), Scalar(-eps * p.V_ri.x()));
}

// No sliding along u at separation.
template <typename Scalar>
Row<Scalar> no_sliding_row(const Problem<Scalar>& p, const Vec3<Scalar>& u) {
  return velocity_row(p, u, Scalar(0));
}

// Impulse ratio along u: u.P = mu P_n (eqs 16, 22, 24).
template <typename Scalar>
Row<Scalar> ratio_row(const Vec3<Scalar>& u, const Scalar& mu) {
  return {Vec3<Scalar>(u - mu * Vec3<Scalar>::UnitX()), Scalar(0)};
}

// No impulse along w (the normal of a solution plane).
template <typename Scalar>
Row<Scalar> no_impulse_row(const Vec3<Scalar>& w) {
  return {w, Scalar(0)};
}

// Empty when the system is singular.
template <typename Scalar>
std::optional<Vec3<Scalar>> solve_rows(const std::array<Row<Scalar>, 3>& rows) {
  Mat3<Scalar> A;
  Vec3<Scalar> b;
  for (int k = 0; k < 3; ++k) {
    A.row(k) = rows[k].c.transpose();
    b(k) = rows[k].rhs;
  }
  if constexpr (is_enclosure_v<Scalar>) {
    const auto x = enclosure_solve<Scalar, 1>(A, b);
    if (!x) return std::nullopt;
    return Vec3<Scalar>(*x);
  } else if constexpr (is_dual_v<Scalar>) {
    using V = typename DualTraits<Scalar>::Value;
    const auto X = dual_solve(A, Eigen::Matrix<Scalar, 3, 1>(b), [](const Mat3<V>& M) {
      Eigen::FullPivLU<Mat3<V>> lu(M);
      return lu.isInvertible() ? std::optional<Eigen::FullPivLU<Mat3<V>>>(lu) : std::nullopt;
    });
    if (!X) return std::nullopt;
    return Vec3<Scalar>(*X);
  } else {
    Eigen::FullPivLU<Mat3<Scalar>> lu(A);
    if (!lu.isInvertible()) return std::nullopt;
    return Vec3<Scalar>(lu.solve(b));
  }
}

// The ratio u.P / P_n at which sliding along u stops, on the plane (n, u): eq 19 (CIR) for the case's
// restitution, eq 20 (GIR) for eps = 0.
template <typename Scalar>
std::optional<Scalar> plane_critical_ratio(const Problem<Scalar>& p, const PlaneAxes<Scalar>& ax, const Scalar& eps) {
  const auto P = solve_rows<Scalar>({restitution_row(p, eps), no_sliding_row(p, ax.u()), no_impulse_row(ax.w())});
  if (!P) return std::nullopt;
  return Scalar(ax.u().dot(*P) / P->x());
}

// Impulse with ratio mu on the plane (n, u) and none along w (eqs 17-18, 22).
template <typename Scalar>
std::optional<Vec3<Scalar>> plane_impulse(const Problem<Scalar>& p, const PlaneAxes<Scalar>& ax, const Scalar& mu) {
  return solve_rows<Scalar>({restitution_row(p, p.restitution), ratio_row(ax.u(), mu), no_impulse_row(ax.w())});
}

}  // namespace impact3d::direct
