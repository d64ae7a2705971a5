// What a reconstruction is compared against, from the states before and after an impulse: Delta-V in
// the vehicle's own axes (as an airbag control module records it), the post-impact speed, heading and
// yaw rate, the deformation energy each vehicle takes and its EES, and the momentum balance.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "impact3d/mechanics/kinematics.hpp"
#include "impact3d/mechanics/decisions.hpp"
#include "impact3d/scalar/planar_norm.hpp"
#include "impact3d/mechanics/rounding.hpp"

namespace impact3d {

template <typename Scalar>
struct VehicleMotion {
  // Delta-V in the vehicle's axes (its orientation does not change during the impulse): x longitudinal
  // (+ forward), y lateral (+ left), z vertical (+ up).
  Vec3<Scalar> dv_B;
  Scalar speed_after{};  // |v_W| after; 0 in exact arithmetic (not rational)
  // Direction of the horizontal CG velocity after, degrees counter-clockwise from world x as yaw is,
  // in (-180, 180]; empty where the horizontal speed is below its rounding, or in exact arithmetic.
  std::optional<Scalar> heading_after_deg;
  Scalar yaw_rate_after{};  // the angular velocity after about the world vertical, (R_WB w_B).z
};

template <typename Scalar>
VehicleMotion<Scalar> vehicle_motion(const RigidBody<Scalar>& before, const RigidBody<Scalar>& after) {
  VehicleMotion<Scalar> m;
  m.dv_B = before.R_WB.transpose() * (after.v_W - before.v_W);
  m.yaw_rate_after = (after.R_WB * after.w_B).z();
  if constexpr (!is_exact_v<Scalar>) {
    using std::atan2;
    m.speed_after = after.v_W.norm();
    // v after = v + P/m, a sum of terms of at most |v| and |Delta-V|.
    const Scalar noise = rounding::arithmetic_roundoff(Scalar(before.v_W.norm() + m.dv_B.norm()));
    const DecisionName<Scalar> name(decision_names::heading_after);
    if (rounding::beyond_rounding(planar_norm(after.v_W.x(), after.v_W.y()), noise))
      m.heading_after_deg = degrees(Scalar(atan2(after.v_W.y(), after.v_W.x())));
  }
  return m;
}

// Deformation energy and EES. The kinetic energy lost goes into both vehicles' deformation (and the
// sliding between them, which no rule separates); E_i = share_i * loss and EES_i = sqrt(2 E_i / m_i),
// the speed at which vehicle i would take E_i against a fixed rigid barrier. The default share is in
// inverse proportion to mass (E_1 : E_2 = m_2 : m_1): equal and opposite contact forces on linear crush
// stiffnesses proportional to mass, E_i = F^2 / (2 k_i).
template <typename Scalar>
std::array<Scalar, 2> energy_share(const std::array<RigidBody<Scalar>, 2>& body,
                                   const std::optional<std::array<Scalar, 2>>& given) {
  if (given) return *given;
  const Scalar total = body[0].mass + body[1].mass;
  return {body[1].mass / total, body[0].mass / total};
}

template <typename Scalar>
struct Deformation {
  std::array<Scalar, 2> share;
  std::array<Scalar, 2> energy;               // share * loss; 0 where the loss is negative
  std::array<std::optional<Scalar>, 2> ees;   // empty for a gain beyond rounding, or in exact arithmetic
};

// What a computed energy loss is: -1 a gain beyond rounding (the energy_gained warning), 0 zero as far
// as the arithmetic can tell (within_rounding: at restitution 1 without sliding it is zero), 1 a loss.
// `roundoff` is the loss's rounding bound (rounding::energy_roundoff).
template <typename Scalar>
int energy_loss_kind(const Scalar& loss, const Scalar& roundoff) {
  const DecisionName<Scalar> name(decision_names::energy_loss_sign);
  if (rounding::within_rounding(loss, roundoff)) return 0;
  return loss < Scalar(0) ? -1 : 1;
}

// A loss within rounding is zero as far as the arithmetic can tell, and so is the EES: sqrt would turn a
// rounding error e of the loss into sqrt(e), far above its bound. A gain beyond rounding has no EES.
template <typename Scalar>
Deformation<Scalar> deformation(const std::array<RigidBody<Scalar>, 2>& body,
                                const std::optional<std::array<Scalar, 2>>& given, const Scalar& loss,
                                const Scalar& roundoff) {
  Deformation<Scalar> d;
  d.share = energy_share(body, given);
  const int kind = energy_loss_kind(loss, roundoff);
  Scalar lost;
  if constexpr (is_enclosure_v<Scalar>) {
    lost = kind > 0 ? loss : Scalar(0);
  } else {
    const DecisionName<Scalar> name(decision_names::energy_loss_sign);
    lost = loss > Scalar(0) ? loss : Scalar(0);
  }
  for (int i = 0; i < 2; ++i) {
    d.energy[i] = d.share[i] * lost;
    if constexpr (!is_exact_v<Scalar>) {
      using std::sqrt;
      if (kind < 0) continue;
      d.ees[i] = kind == 0 ? Scalar(0) : Scalar(sqrt(Scalar(Scalar(2) * d.energy[i] / body[i].mass)));
    }
  }
  return d;
}

// The momentum balance, before and after, with each residual over its rounding bound (rounding.hpp,
// kMomentumRoundings): at most 1 when the post-impact states conserve momentum.
template <typename Scalar>
struct MomentumCheck {
  Vec3<Scalar> linear_before_W, linear_after_W;  // m1 v1 + m2 v2, world axes
  // Each vehicle's angular momentum about its impulse centre, in its own axes (where the balance holds
  // whatever the rounding of its rotation): J w + m (-p_CgIc) x (R^T v).
  std::array<Vec3<Scalar>, 2> angular_before_B, angular_after_B;
  Scalar linear_residual;                  // |after - before|_inf / bound
  std::array<Scalar, 2> angular_residual;
};

namespace reconstruction_detail {
template <typename Scalar>
Scalar norm1(const Vec3<Scalar>& v) {
  using std::abs;
  return abs(v.x()) + abs(v.y()) + abs(v.z());
}
template <typename Scalar>
Scalar norm_inf(const Vec3<Scalar>& v) {
  using std::abs;
  Scalar m = abs(v.x());
  for (int k = 1; k < 3; ++k)
    if (abs(v[k]) > m) m = abs(v[k]);
  return m;
}
// Largest column sum of |J|: |J w|_1 <= ||J||_1 |w|_1.
template <typename Scalar>
Scalar matrix_norm1(const Mat3<Scalar>& J) {
  Scalar m(0);
  for (int c = 0; c < 3; ++c) {
    const Scalar col = norm1(Vec3<Scalar>(J.col(c)));
    if (col > m) m = col;
  }
  return m;
}
// An enclosure's residual: 0 when every component's enclosure holds zero, as the exact balance does;
// infinite otherwise, a defect of the program (the balance is proven violated).
template <typename Scalar>
Scalar enclosure_residual(const Vec3<Scalar>& r) {
  for (int k = 0; k < 3; ++k)
    if (!r[k].contains_zero()) return std::numeric_limits<Scalar>::infinity();
  return Scalar(0);
}
// residual / bound. In exact arithmetic the balance is an identity of the rational operations, so a
// residual there is a defect of the program, not of the case.
template <typename Scalar>
Scalar over_bound(const Scalar& residual, const Scalar& bound) {
  if (residual == Scalar(0)) return Scalar(0);
  if constexpr (is_exact_v<Scalar>) throw std::logic_error("momentum not conserved in exact arithmetic");
  else if (!(bound > Scalar(0))) return std::numeric_limits<Scalar>::infinity();
  else return residual / bound;
}
template <typename Scalar>
Vec3<Scalar> angular_about_Ic_B(const RigidBody<Scalar>& b) {
  return b.J_B * b.w_B - b.p_CgIc_B.cross(Vec3<Scalar>(b.mass * (b.R_WB.transpose() * b.v_W)));
}
}  // namespace reconstruction_detail

template <typename Scalar>
MomentumCheck<Scalar> momentum_check(const std::array<RigidBody<Scalar>, 2>& before,
                                     const std::array<RigidBody<Scalar>, 2>& after) {
  namespace d = reconstruction_detail;
  MomentumCheck<Scalar> m;
  m.linear_before_W = before[0].mass * before[0].v_W + before[1].mass * before[1].v_W;
  m.linear_after_W = after[0].mass * after[0].v_W + after[1].mass * after[1].v_W;
  Scalar scale(0);
  for (int i = 0; i < 2; ++i) scale += before[i].mass * (d::norm1(before[i].v_W) + d::norm1(after[i].v_W));
  if constexpr (is_enclosure_v<Scalar>) {
    m.linear_residual = d::enclosure_residual(Vec3<Scalar>(m.linear_after_W - m.linear_before_W));
    for (int i = 0; i < 2; ++i) {
      m.angular_before_B[i] = d::angular_about_Ic_B(before[i]);
      m.angular_after_B[i] = d::angular_about_Ic_B(after[i]);
      m.angular_residual[i] = d::enclosure_residual(Vec3<Scalar>(m.angular_after_B[i] - m.angular_before_B[i]));
    }
    return m;
  }
  m.linear_residual = d::over_bound(d::norm_inf(Vec3<Scalar>(m.linear_after_W - m.linear_before_W)),
                                    rounding::momentum_roundoff(scale));
  for (int i = 0; i < 2; ++i) {
    const auto& b = before[i];
    const auto& a = after[i];
    m.angular_before_B[i] = d::angular_about_Ic_B(b);
    m.angular_after_B[i] = d::angular_about_Ic_B(a);
    const Scalar s = d::matrix_norm1(b.J_B) * (d::norm1(b.w_B) + d::norm1(a.w_B)) +
                     Scalar(2) * b.mass * d::norm1(b.p_CgIc_B) *
                         (d::norm1(Vec3<Scalar>(b.R_WB.transpose() * b.v_W)) + d::norm1(Vec3<Scalar>(a.R_WB.transpose() * a.v_W)));
    m.angular_residual[i] = d::over_bound(d::norm_inf(Vec3<Scalar>(m.angular_after_B[i] - m.angular_before_B[i])),
                                          rounding::momentum_roundoff(s));
  }
  return m;
}

}  // namespace impact3d
