// One collision as raw parameters, the way a case file writes them when the contact frame is given by
// angles: masses, full inertia tensors, orientations and the contact frame in degrees (active intrinsic
// z-y'-x''), velocities, impulse centres, restitution, all in SI units. What the lean path and the SIMD
// batches (batch/columns.hpp) start from.
#pragma once

#include <algorithm>
#include <array>
#include <type_traits>

#include "impact3d/mechanics/batch/sin_cos.hpp"
#include "impact3d/scalar/lean_twin.hpp"
#include "impact3d/mechanics/rotation.hpp"
#include "impact3d/scalar/scalars.hpp"
#include "impact3d/mechanics/scene.hpp"

namespace impact3d {

template <typename Scalar>
struct RawVehicle {
  Scalar mass;
  Mat3<Scalar> J_B;                       // inertia tensor about the CG, body axes (its upper triangle is read)
  Scalar yaw_deg, pitch_deg, roll_deg;    // body -> world
  Vec3<Scalar> v_W, w_B, p_CgIc_B;        // CG velocity (world), angular velocity (body), impulse centre (body)
};

template <typename Scalar>
struct RawCollision {
  std::array<RawVehicle<Scalar>, 2> vehicle;
  Scalar normal_yaw_deg, normal_pitch_deg, tangent_roll_deg;  // contact -> world
  Scalar restitution;
};

// The scene of the raw parameters in the scalar's own arithmetic (scene_of below takes its lean twin).
template <typename Scalar>
Scene<Scalar> compute_scene(const RawCollision<Scalar>& c) {
  const Scalar deg[9] = {c.vehicle[0].yaw_deg, c.vehicle[0].pitch_deg, c.vehicle[0].roll_deg,
                         c.vehicle[1].yaw_deg, c.vehicle[1].pitch_deg, c.vehicle[1].roll_deg,
                         c.normal_yaw_deg,     c.normal_pitch_deg,     c.tangent_roll_deg};
  SinCos<Scalar> sc[9];
  if constexpr (std::is_same_v<Scalar, double>) {
    double in[16] = {}, s[16], co[16];  // two groups of eight lanes, padded with zeros
    std::copy(deg, deg + 9, in);
    batch::sin_cos_deg_columns(in, s, co, 16);
    for (int k = 0; k < 9; ++k) sc[k] = {s[k], co[k]};
  } else {
    for (int k = 0; k < 9; ++k) sc[k] = sin_cos_deg(deg[k]);
  }
  // Written in place, member by member: building bodies as temporaries and copying them in cost more
  // than the arithmetic (stores forwarded to wider loads).
  Scene<Scalar> s;
  for (int i = 0; i < 2; ++i) {
    const RawVehicle<Scalar>& v = c.vehicle[i];
    RigidBody<Scalar>& b = s.body[i];
    b.mass = v.mass;
    // Symmetric by construction: the condition bounds read the upper triangle, Eigen's solves the lower.
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) b.J_B(row, col) = row <= col ? v.J_B(row, col) : v.J_B(col, row);
    b.R_WB = rotation_zyx(sc[3 * i], sc[3 * i + 1], sc[3 * i + 2]);
    b.v_W = v.v_W;
    b.w_B = v.w_B;
    b.p_CgIc_B = v.p_CgIc_B;
  }
  s.R_WC = rotation_zyx(sc[6], sc[7], sc[8]);
  s.restitution = c.restitution;
  return s;
}

// The raw parameters in the scalar's lean twin (lean_twin.hpp), exactly.
template <typename Scalar>
RawCollision<lean_twin_t<Scalar>> twin_of(const RawCollision<Scalar>& c) {
  using Twin = LeanTwin<Scalar>;
  using T = typename Twin::type;
  const auto to = [](const Scalar& x) { return Twin::to(x); };
  RawCollision<T> twin;
  for (int i = 0; i < 2; ++i) {
    const RawVehicle<Scalar>& v = c.vehicle[i];
    twin.vehicle[i] = {to(v.mass), convert_each<T>(v.J_B, to), to(v.yaw_deg), to(v.pitch_deg), to(v.roll_deg),
                       convert_each<T>(v.v_W, to), convert_each<T>(v.w_B, to), convert_each<T>(v.p_CgIc_B, to)};
  }
  twin.normal_yaw_deg = to(c.normal_yaw_deg), twin.normal_pitch_deg = to(c.normal_pitch_deg);
  twin.tangent_roll_deg = to(c.tangent_roll_deg), twin.restitution = to(c.restitution);
  return twin;
}

// The scene of the raw parameters, rotations in closed form (rotation_zyx). In double the nine sines and
// cosines are taken together on SIMD lanes (batch/sin_cos.hpp, within 4 ulps of sin_cos_deg): one case's
// angles to rotations, the largest cost of a lean solve from raw parameters, in a few vector operations.
// A scalar with a lean twin (lean_twin.hpp) is computed in the twin: the same scene, faster.
template <typename Scalar>
Scene<Scalar> scene_of(const RawCollision<Scalar>& c) {
  if constexpr (has_lean_twin_v<Scalar>) {
    using Twin = LeanTwin<Scalar>;
    return convert_scene<Scalar>(compute_scene(twin_of(c)), [](const typename Twin::type& x) { return Twin::from(x); });
  } else {
    return compute_scene(c);
  }
}

}  // namespace impact3d
