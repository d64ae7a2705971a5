// One collision as raw parameters, the way a case file writes them when the contact frame is given by
// angles: masses, full inertia tensors, orientations and the contact frame in degrees (active intrinsic
// z-y'-x''), velocities, impulse centres, restitution, all in SI units. What the lean path and the SIMD
// batches (batch/columns.hpp) start from.
#pragma once

#include <array>

#include "impact3d/numeric/rotation.hpp"
#include "impact3d/numeric/scene.hpp"

namespace impact3d {

template <typename Scalar>
struct RawVehicle {
  Scalar mass;
  Mat3<Scalar> J_B;                       // inertia tensor about the CG, body axes
  Scalar yaw_deg, pitch_deg, roll_deg;    // body -> world
  Vec3<Scalar> v_W, w_B, p_CgIc_B;        // CG velocity (world), angular velocity (body), impulse centre (body)
};

template <typename Scalar>
struct RawCollision {
  std::array<RawVehicle<Scalar>, 2> vehicle;
  Scalar normal_yaw_deg, normal_pitch_deg, tangent_roll_deg;  // contact -> world
  Scalar restitution;
};

// The scene of the raw parameters, rotations in closed form (rotation_zyx_deg_closed).
template <typename Scalar>
Scene<Scalar> scene_of(const RawCollision<Scalar>& c) {
  Scene<Scalar> s;
  for (int i = 0; i < 2; ++i) {
    const RawVehicle<Scalar>& v = c.vehicle[i];
    s.body[i] = {v.mass, v.J_B, rotation_zyx_deg_closed(v.yaw_deg, v.pitch_deg, v.roll_deg), v.v_W, v.w_B, v.p_CgIc_B};
  }
  s.R_WC = rotation_zyx_deg_closed(c.normal_yaw_deg, c.normal_pitch_deg, c.tangent_roll_deg);
  s.restitution = c.restitution;
  return s;
}

}  // namespace impact3d
