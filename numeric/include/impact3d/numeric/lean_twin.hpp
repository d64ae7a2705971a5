// The type the lean path (lean.hpp, raw_collision.hpp) computes a scalar's results in: the scalar itself,
// or a twin whose every operation gives the same value bit for bit, only faster. multiprecision.hpp pairs
// MPFR's 100 digits with FixedFloat<334> (fixed_float.hpp); tests/check_fixed_float.cpp holds each
// operation, and the lean route as a whole, to MPFR's.
#pragma once

#include <type_traits>

#include "impact3d/numeric/scene.hpp"

namespace impact3d {

template <typename Scalar>
struct LeanTwin {
  using type = Scalar;
  static const Scalar& to(const Scalar& x) { return x; }
  static const Scalar& from(const Scalar& x) { return x; }
};
template <typename Scalar>
using lean_twin_t = typename LeanTwin<Scalar>::type;
template <typename Scalar>
inline constexpr bool has_lean_twin_v = !std::is_same_v<lean_twin_t<Scalar>, Scalar>;

// Each number of a matrix or vector by f.
template <typename To, typename F, typename Derived>
Eigen::Matrix<To, Derived::RowsAtCompileTime, Derived::ColsAtCompileTime> convert_each(const Eigen::MatrixBase<Derived>& m, F&& f) {
  Eigen::Matrix<To, Derived::RowsAtCompileTime, Derived::ColsAtCompileTime> out;
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) out(i, j) = f(m(i, j));
  return out;
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
