// Rigid-body kinematics at the impulse centre (paper eqs 4-6), independent of any impulse law.
#pragma once

#include "impact3d/mechanics/scene.hpp"

namespace impact3d {

// The paper's T_i (eq 5): vehicle coordinates -> contact coordinates.
template <typename Scalar>
Mat3<Scalar> R_CB(const Scene<Scalar>& s, int i) {
  return s.R_WC.transpose() * s.body[i].R_WB;
}

template <typename Scalar>
Scalar reduced_mass(const Scene<Scalar>& s) {
  return s.body[0].mass * s.body[1].mass / (s.body[0].mass + s.body[1].mass);
}

// Velocity of the material point at the impulse centre, world axes.
template <typename Scalar>
Vec3<Scalar> v_Ic_W(const RigidBody<Scalar>& b) {
  return b.v_W + b.R_WB * b.w_B.cross(b.p_CgIc_B);
}

// V_rel = T2 V_IC2 - T1 V_IC1 in contact axes (eq 6): positive normal component means approach.
template <typename Scalar>
Vec3<Scalar> relative_velocity_C(const Scene<Scalar>& s, const Vec3<Scalar>& v_Ic0_W, const Vec3<Scalar>& v_Ic1_W) {
  return s.R_WC.transpose() * (v_Ic1_W - v_Ic0_W);
}
template <typename Scalar>
Vec3<Scalar> relative_velocity_C(const Scene<Scalar>& s) {
  return relative_velocity_C(s, v_Ic_W(s.body[0]), v_Ic_W(s.body[1]));
}

template <typename Scalar>
Scalar kinetic_energy(const RigidBody<Scalar>& b) {
  return (b.mass * b.v_W.squaredNorm() + b.w_B.dot(b.J_B * b.w_B)) / Scalar(2);
}

// Angular momentum about the world point where the impulse centre is at the instant of impact.
// An impulse applied there has no moment about it, so this is conserved by every impulse law.
template <typename Scalar>
Vec3<Scalar> angular_momentum_about_Ic_W(const RigidBody<Scalar>& b) {
  const Vec3<Scalar> p_IcCg_W = -(b.R_WB * b.p_CgIc_B);
  return b.R_WB * (b.J_B * b.w_B) + p_IcCg_W.cross(b.mass * b.v_W);
}

}  // namespace impact3d
