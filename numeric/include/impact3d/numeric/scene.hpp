// The physical input of one collision, in SI units and the contract's frames.
#pragma once

#include <array>
#include <optional>

#include "impact3d/numeric/types.hpp"

namespace impact3d {

template <typename Scalar>
struct RigidBody {
  Scalar mass;
  Mat3<Scalar> J_B;        // inertia tensor about the CG, body axes (H = J w)
  Mat3<Scalar> R_WB;       // body -> world
  Vec3<Scalar> v_W;        // CG velocity, world axes
  Vec3<Scalar> w_B;        // angular velocity, body axes
  Vec3<Scalar> p_CgIc_B;   // impulse centre relative to the CG, body axes
};

template <typename Scalar>
struct Scene {
  std::array<RigidBody<Scalar>, 2> body;
  Mat3<Scalar> R_WC;  // contact -> world; columns n, t, z (n points into body 0, "vehicle 1")
  Scalar restitution;
  // The share of the kinetic energy lost that each vehicle's deformation takes (summing to 1), for EES;
  // empty: in inverse proportion to mass (reconstruction.hpp).
  std::optional<std::array<Scalar, 2>> energy_share;
};

}  // namespace impact3d
