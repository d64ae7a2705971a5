// The physical input of one collision, in SI units and the contract's frames.
#pragma once

#include <array>
#include <optional>
#include <stdexcept>
#include <string>

#include "impact3d/scalar/lean_twin.hpp"
#include "impact3d/scalar/types.hpp"

namespace impact3d {

template <typename Scalar>
struct RigidBody {
  Scalar mass;
  Mat3<Scalar> J_B;        // inertia tensor about the CG, body axes (H = J w); symmetric (require_symmetric_inertia)
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

// Throws std::invalid_argument unless each body's J_B equals its transpose entry for entry. The
// generated kernels and the condition bounds read the upper triangle, Cholesky and the eigen-solver the
// lower, the energies and momenta the whole: a tensor that is not symmetric has no single meaning, and
// each would answer a different collision. Case files (read_case) refuse such a tensor before a Scene
// is made, and the Python module's solve_batch flags its row; analyze, exact_analyze, certified_analyze
// and solve_lean check a Scene given to them. An enclosure's entries must be the same ball, a dual
// number's the same value and derivatives; a NaN entry of the other types is left to the not-finite
// warnings.
template <typename Scalar>
void require_symmetric_inertia(const Scene<Scalar>& s) {
  auto same = [](const Scalar& a, const Scalar& b) {
    if constexpr (is_enclosure_v<Scalar>) return EnclosureTraits<Scalar>::identical(a, b);
    else if constexpr (is_dual_v<Scalar>)
      return !(a < b) && !(b < a) && (a.derivatives().array() == b.derivatives().array()).all();
    else return !(a < b) && !(b < a);
  };
  for (int i = 0; i < 2; ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = r + 1; c < 3; ++c)
        if (!same(s.body[i].J_B(r, c), s.body[i].J_B(c, r)))
          throw std::invalid_argument("body[" + std::to_string(i) + "].J_B is not symmetric: entry (" + std::to_string(r) +
                                      ", " + std::to_string(c) + ") differs from entry (" + std::to_string(c) + ", " +
                                      std::to_string(r) + ")");
}

// A scene's numbers by f (exact where f is: a scalar and its twin).
template <typename To, typename From, typename F>
Scene<To> convert_scene(const Scene<From>& s, F&& f) {
  Scene<To> out;
  for (int i = 0; i < 2; ++i) {
    const RigidBody<From>& b = s.body[i];
    out.body[i] = {f(b.mass), convert_each<To>(b.J_B, f), convert_each<To>(b.R_WB, f), convert_each<To>(b.v_W, f),
                   convert_each<To>(b.w_B, f), convert_each<To>(b.p_CgIc_B, f)};
  }
  out.R_WC = convert_each<To>(s.R_WC, f);
  out.restitution = f(s.restitution);
  if (s.energy_share) out.energy_share = std::array<To, 2>{f((*s.energy_share)[0]), f((*s.energy_share)[1])};
  return out;
}

}  // namespace impact3d
