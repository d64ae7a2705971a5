// What an impulse does to the two vehicles: post-impact states, Delta-V and its principal direction of
// force, relative velocity and sliding after, swerve, kinetic energy, and the physical warnings.
// Everything here is computed from the states, not from K, so that it also checks the engines.
#pragma once

#include <Eigen/Cholesky>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "impact3d/mechanics/constraint_rows.hpp"
#include "impact3d/mechanics/decisions.hpp"
#include "impact3d/mechanics/kinematics.hpp"
#include "impact3d/scalar/planar_norm.hpp"
#include "impact3d/mechanics/reconstruction.hpp"
#include "impact3d/mechanics/rounding.hpp"
#include "impact3d/mechanics/strategy.hpp"

namespace impact3d {

template <typename Scalar>
RigidBody<Scalar> apply_impulse(const RigidBody<Scalar>& b, const Vec3<Scalar>& P_W) {
  RigidBody<Scalar> a = b;
  a.v_W += P_W / b.mass;
  const Vec3<Scalar> P_B = b.R_WB.transpose() * P_W;
  a.w_B += spd_solve(b.J_B, Vec3<Scalar>(b.p_CgIc_B.cross(P_B)));
  return a;
}

template <typename Scalar>
struct BodyChange {
  Vec3<Scalar> dv_W;  // change of CG velocity, world axes
  Scalar dv{};        // its magnitude (0 in exact arithmetic, where it is not rational)
  // Principal direction of force on the vehicle, degrees clockwise from straight ahead seen from above
  // (0 = frontal, 90 = right side, 270 = left side), from the body-axes x-y part of Delta-V; and its
  // clock position (12 = frontal). Empty when Delta-V has no body x-y part.
  std::optional<Scalar> pdof_deg;
  std::optional<int> clock;
};

template <typename Scalar>
BodyChange<Scalar> body_change(const RigidBody<Scalar>& before, const RigidBody<Scalar>& after) {
  using std::atan2;
  using std::floor;
  BodyChange<Scalar> c;
  c.dv_W = after.v_W - before.v_W;
  if constexpr (!is_exact_v<Scalar>) {  // |Delta-V| and its angle are not rational
    c.dv = c.dv_W.norm();
    const Vec3<Scalar> dv_B = before.R_WB.transpose() * c.dv_W;
    const DecisionName<Scalar> name(decision_names::pdof);
    if (rounding::beyond_rounding(planar_norm(dv_B.x(), dv_B.y()), rounding::pdof_roundoff(c.dv))) {
      // The force is along Delta-V; it comes from the side opposite to it.
      Scalar deg = degrees(Scalar(atan2(dv_B.y(), Scalar(-dv_B.x()))));
      if (deg < Scalar(0)) deg += Scalar(360);
      c.pdof_deg = deg;
      const Scalar hours = deg / Scalar(30) + ratio<Scalar>(1, 2);
      const Scalar whole = floor(hours);
      // An enclosure's floor is its midpoint's: whether the whole ball lies in [whole, whole + 1) is the
      // clock's decision, recorded under the PDOF's name where it is not certain.
      if constexpr (is_enclosure_v<Scalar>) (void)(whole <= hours && hours < whole + Scalar(1));
      int hour = static_cast<int>(to_double(whole)) % 12;
      c.clock = hour == 0 ? 12 : hour;
    }
  }
  return c;
}

// How the post-impact relative velocity along one axis compares with the initial one.
enum class AxisChange { none, started, continued, stopped, reversed };

inline const char* axis_change_name(AxisChange c) {
  switch (c) {
    case AxisChange::none: return "none";
    case AxisChange::started: return "started";
    case AxisChange::continued: return "continued";
    case AxisChange::stopped: return "stopped";
    case AxisChange::reversed: return "reversed";
  }
  return "?";
}

// `rows(was_zero)`: what the constraint rows say of `after` (constraint_rows.hpp).
template <typename Scalar, typename Rows>
AxisChange axis_change(const Scalar& before, const Scalar& after, const Scalar& tol, Rows&& rows) {
  const bool was = rounding::beyond_rounding(before, tol);
  const ZeroAnswer a = zero_or_by_rows(after, tol, [&] { return rows(!was); });
  const bool is = !a.zero;
  if (!was) return is ? AxisChange::started : AxisChange::none;
  if (!is) return AxisChange::stopped;
  if (a.by_rows) return AxisChange::reversed;  // only a Full Impact's -eps V_ri, eps > 0, is not zero by its rows
  return (before > Scalar(0)) == (after > Scalar(0)) ? AxisChange::continued : AxisChange::reversed;
}

template <typename Scalar>
AxisChange axis_change(const Scalar& before, const Scalar& after, const Scalar& tol) {
  return axis_change(before, after, tol, [](bool) { return RowsAnswer{}; });
}

template <typename Scalar>
struct Solution {
  ImpulseSolution<Scalar> impulse;
  Vec3<Scalar> P_W;                            // impulse on vehicle 1, world axes
  std::array<RigidBody<Scalar>, 2> after;      // post-impact states
  std::array<BodyChange<Scalar>, 2> change;
  Vec3<Scalar> V_ri, V_rf;                     // relative velocity at the impulse centre, contact axes
  Scalar velocity_roundoff;                    // post-impact relative velocities below this are zero (rounding.hpp)
  Scalar restitution_effective;                // -V_rnf / V_rni
  Scalar sliding_before{}, sliding_after{};    // |(V_rt, V_rz)|; 0 in exact arithmetic (not rational)
  // Final sliding resolved on the initial sliding direction u (t, z): `sliding_along` the component along
  // u, `swerve_speed` the component across it (t towards z). `swerve_deg`: the angle of the final sliding
  // off the line of u, atan2(across, |along|) in [-90, 90], and `reversed` whether it points back along
  // that line (along < 0 beyond rounding): a reversal is not a swerve.
  std::optional<Scalar> sliding_along;
  std::optional<Scalar> swerve_deg;
  std::optional<Scalar> swerve_speed;
  std::optional<bool> reversed;
  AxisChange t_change, z_change;
  std::string volume;                          // paper Figure 2: A-D, or the plane the solution lies on
  Scalar energy_before, energy_after, energy_loss;
  std::array<VehicleMotion<Scalar>, 2> motion;
  Deformation<Scalar> deformation;
  MomentumCheck<Scalar> momentum;
  // Relative rounding bound of the impulse and its ratios at this precision (rounding.hpp); 0 in exact
  // arithmetic, infinite where K or J is not positive definite at this precision.
  Scalar rounding_bound = Scalar(0);
  std::vector<Warning> warnings;
};

// kappa: condition number of K, which bounds how far a computed zero can stray from zero.
template <typename Scalar>
Solution<Scalar> post_impact(const Scene<Scalar>& s, const ImpulseSolution<Scalar>& imp, const Scalar& kappa) {
  using std::abs;
  using std::atan2;
  Solution<Scalar> out;
  out.impulse = imp;
  out.warnings = imp.warnings;
  out.P_W = s.R_WC * imp.P_C;
  out.after = {apply_impulse(s.body[0], out.P_W), apply_impulse(s.body[1], Vec3<Scalar>(-out.P_W))};
  for (int i = 0; i < 2; ++i) out.change[i] = body_change(s.body[i], out.after[i]);

  Scene<Scalar> s_after = s;
  s_after.body = out.after;
  out.V_ri = relative_velocity_C(s);
  out.V_rf = relative_velocity_C(s_after);
  // Post-impact relative velocity is a difference of point velocities, through a solve of condition
  // kappa: below `tol` it is zero to the precision of the computation.
  const Scalar tol = rounding::velocity_roundoff(s, kappa);
  out.velocity_roundoff = tol;

  out.restitution_effective = -out.V_rf.x() / out.V_ri.x();
  const std::optional<bool> eps_zero = restitution_zero(s.restitution);
  if constexpr (!is_exact_v<Scalar>) {  // sliding speeds and the swerve are not rational
    out.sliding_before = planar_norm(out.V_ri.y(), out.V_ri.z());
    out.sliding_after = planar_norm(out.V_rf.y(), out.V_rf.z());
    const DecisionName<Scalar> name(decision_names::swerve);
    if (rounding::beyond_rounding(out.sliding_before, tol)) {
      const Scalar cross = out.V_ri.y() * out.V_rf.z() - out.V_ri.z() * out.V_rf.y();
      const Scalar dot = out.V_ri.y() * out.V_rf.y() + out.V_ri.z() * out.V_rf.z();
      out.swerve_speed = cross / out.sliding_before;
      out.sliding_along = dot / out.sliding_before;
      const auto zeros = [&] { return plane_zeros(imp.rows, out.V_ri, out.V_rf); };
      if (!zero_or_by_rows(out.sliding_after, tol, [&] { return sliding_after(imp.rows, zeros(), eps_zero); }).zero) {
        // A component within rounding of zero is zero (the report's rule): the final sliding is then on
        // the line, or square to it, exactly; and the angle keeps no kink of |along| at along = 0.
        const ZeroAnswer along = zero_or_by_rows(*out.sliding_along, tol, [&] { return swerve_along(imp.rows, zeros(), eps_zero); });
        if (zero_or_by_rows(*out.swerve_speed, tol, [&] { return swerve_across(imp.rows, zeros()); }).zero) out.swerve_deg = Scalar(0);
        else if (along.zero) out.swerve_deg = Scalar(cross > Scalar(0) ? 90 : -90);
        else out.swerve_deg = degrees(Scalar(atan2(cross, abs(dot))));
        // Not zero by the rows is a Full Impact's -eps |sliding before|, eps > 0: pointing back.
        out.reversed = !along.zero && (along.by_rows || *out.sliding_along < Scalar(0));
      }
    }
  }
  {
    const DecisionName<Scalar> name(decision_names::volume);
    out.t_change = axis_change(out.V_ri.y(), out.V_rf.y(), tol, [&](bool was_zero) {
      return axis_after(imp.rows, 1, was_zero, eps_zero, exactly_zero(out.V_ri.z()));
    });
  }
  {
    const DecisionName<Scalar> name(decision_names::z_sliding);
    out.z_change = axis_change(out.V_ri.z(), out.V_rf.z(), tol, [&](bool was_zero) {
      return axis_after(imp.rows, 2, was_zero, eps_zero, exactly_zero(out.V_ri.y()));
    });
  }
  bool separating, penetrating;
  {
    const DecisionName<Scalar> name(decision_names::volume);
    const ZeroAnswer n = zero_or_by_rows(out.V_rf.x(), tol, [&] { return normal_after(eps_zero); });
    // Not zero by the rows is -eps V_rn before, eps > 0: separating.
    separating = !n.zero && (n.by_rows || out.V_rf.x() < Scalar(0));
    penetrating = !n.zero && !n.by_rows && out.V_rf.x() > Scalar(0);
  }
  if (!separating && !penetrating)
    out.volume = "max-compression plane";
  else if (out.t_change == AxisChange::stopped || out.t_change == AxisChange::none)
    out.volume = "t no-sliding plane";
  else if (out.t_change == AxisChange::started)
    out.volume = "none (no initial t sliding)";
  else if (out.t_change == AxisChange::continued)
    out.volume = separating ? "A" : "D";
  else
    out.volume = separating ? "B" : "C";

  out.energy_before = kinetic_energy(s.body[0]) + kinetic_energy(s.body[1]);
  out.energy_after = kinetic_energy(out.after[0]) + kinetic_energy(out.after[1]);
  out.energy_loss = out.energy_before - out.energy_after;

  bool compressive;
  {
    const DecisionName<Scalar> name(decision_names::normal_impulse_sign);
    compressive = imp.P_C.x() > Scalar(0);
  }
  if (!compressive)
    out.warnings.push_back({WarningCode::tensile_normal_impulse,
                            "normal impulse P_n <= 0: the constraints demand a pulling contact"});
  // The loss is a difference of energies of size energy_before; at restitution 1 it is zero in exact
  // arithmetic.
  const Scalar energy_roundoff = rounding::energy_roundoff(kappa, out.energy_before);
  if (energy_loss_kind(out.energy_loss, energy_roundoff) < 0) out.warnings.push_back({WarningCode::energy_gained, "kinetic energy gained: loss < 0"});

  for (int i = 0; i < 2; ++i) out.motion[i] = vehicle_motion(s.body[i], out.after[i]);
  out.deformation = deformation(s.body, s.energy_share, out.energy_loss, energy_roundoff);
  out.momentum = momentum_check(s.body, out.after);
  const auto& m = out.momentum;
  if constexpr (is_enclosure_v<Scalar>) {  // 0 or infinite (reconstruction.hpp): a defect, not a decision
    if (!m.linear_residual.finite() || !m.angular_residual[0].finite() || !m.angular_residual[1].finite())
      out.warnings.push_back({WarningCode::momentum_residual, "the post-impact states' enclosures exclude the momentum balance"});
  } else if (m.linear_residual > Scalar(1) || m.angular_residual[0] > Scalar(1) || m.angular_residual[1] > Scalar(1))
    out.warnings.push_back({WarningCode::momentum_residual,
                            "the post-impact states miss the momentum balance by more than its rounding bound"});
  return out;
}

}  // namespace impact3d
