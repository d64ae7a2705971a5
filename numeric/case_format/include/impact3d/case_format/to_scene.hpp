// From a validated case to SI Scene and strategies in the target precision; the checks that need
// arithmetic (positive definiteness, degenerate contact vectors, approach) happen here.
#pragma once

#include <Eigen/Cholesky>
#include <utility>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/present.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/mechanics/kinematics.hpp"
#include "impact3d/mechanics/rotation.hpp"
#include "impact3d/mechanics/rounding.hpp"
#include "impact3d/mechanics/strategies/list.hpp"
#include "impact3d/mechanics/units.hpp"

namespace impact3d::case_format {

// The numbers of a case a conversion to a dual type seeds (sensitivity.cpp sets it around one
// conversion): the number of input j, for j in [first, first + the dual's width), gets derivative 1 in
// entry j - first; every other number derivative 0.
struct DualSeeds {
  std::vector<std::pair<const Number*, int>> index;
  int first = 0;
};
inline thread_local const DualSeeds* dual_seeds = nullptr;

// Installs `seeds` on this thread for its lifetime.
class DualSeedScope {
 public:
  explicit DualSeedScope(const DualSeeds& s) : previous_(dual_seeds) { dual_seeds = &s; }
  ~DualSeedScope() { dual_seeds = previous_; }
  DualSeedScope(const DualSeedScope&) = delete;
  DualSeedScope& operator=(const DualSeedScope&) = delete;

 private:
  const DualSeeds* previous_;
};

template <typename Scalar>
Scalar to_scalar(const Number& n) {
  if constexpr (is_dual_v<Scalar>) {
    Scalar x(scalar_from_text<typename DualTraits<Scalar>::Value>(n.text));
    x.derivatives().setZero();
    if (!dual_seeds) return x;
    for (const auto& [number, j] : dual_seeds->index)
      if (number == &n && j >= dual_seeds->first && j - dual_seeds->first < x.derivatives().size())
        x.derivatives()[j - dual_seeds->first] = 1;
    return x;
  } else if constexpr (std::is_same_v<Scalar, double>) {
    return n.value;  // the literal correctly rounded, as scalar_from_text<double> would give it
  } else {
    return scalar_from_text<Scalar>(n.text);
  }
}

template <typename Scalar>
Vec3<Scalar> to_vec3(const Vector3& v, const Scalar& factor) {
  return Vec3<Scalar>(to_scalar<Scalar>(v[0]), to_scalar<Scalar>(v[1]), to_scalar<Scalar>(v[2])) * factor;
}

template <typename Scalar>
Mat3<Scalar> contact_rotation(const ContactSpec& c) {
  if (!c.by_vectors)
    return rotation_zyx_deg(to_scalar<Scalar>(c.normal_yaw), to_scalar<Scalar>(c.normal_pitch),
                            to_scalar<Scalar>(c.tangent_roll));
  const Vec3<Scalar> n = to_vec3(c.normal, Scalar(1)), t = to_vec3(c.tangent, Scalar(1));
  if (n.squaredNorm() == Scalar(0)) throw CaseError(c.path + ".normal", "zero vector");
  // Parallel when the tangent has too little component across the normal to build a frame from
  // (rounding::parallel_within_rounding).
  const Scalar across = n.cross(t).squaredNorm(), scale = n.squaredNorm() * t.squaredNorm();
  if (rounding::parallel_within_rounding(across, scale))
    throw CaseError(c.path + ".tangent", "zero or parallel to the normal");
  return contact_frame_from_vectors(n, t);
}

// A proper rotation: exactly in exact arithmetic; otherwise R R^T = I within
// rounding::orthonormality_tolerance (decimals written to 13 or more digits pass) and det R > 0.
template <typename Scalar>
void check_rotation(const Mat3<Scalar>& R, const std::string& path) {
  const Mat3<Scalar> E = R * R.transpose() - Mat3<Scalar>::Identity();
  Scalar worst(0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      using std::abs;
      if (abs(E(i, j)) > worst) worst = abs(E(i, j));
    }
  const bool orthonormal =
      is_exact_v<Scalar> ? worst == Scalar(0) : worst <= rounding::orthonormality_tolerance<Scalar>();
  if (!orthonormal) {
    std::string by;  // the same three digits at every precision
    if constexpr (is_exact_v<Scalar>) by = scalar_to_text(worst.template convert_to<double>(), 3);
    else by = scalar_to_text(Scalar(worst), 3);
    throw CaseError(path, "not a rotation: R R^T differs from I by " + by);
  }
  if (!(R.determinant() > Scalar(0))) throw CaseError(path, "not a rotation: its determinant is negative (a reflection)");
}

template <typename Scalar>
RigidBody<Scalar> to_body(const VehicleSpec& v, const UnitFactors<Scalar>& f) {
  RigidBody<Scalar> b;
  b.mass = to_scalar<Scalar>(v.mass) * f.mass;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b.J_B(i, j) = to_scalar<Scalar>(v.inertia[i][j]) * f.inertia;
  // The reader checked the tensor positive definite exactly as written. A precision that rounds it to an
  // indefinite one is not an input error: its results carry a rounding warning (rounding.hpp).
  if (v.orientation_matrix) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) b.R_WB(i, j) = to_scalar<Scalar>((*v.orientation_matrix)[i][j]);
    check_rotation(b.R_WB, v.orientation_path);
  } else {
    b.R_WB = rotation_zyx_deg(to_scalar<Scalar>(v.yaw), to_scalar<Scalar>(v.pitch), to_scalar<Scalar>(v.roll));
  }
  b.v_W = to_vec3(v.velocity, f.velocity);
  b.w_B = to_vec3(v.angular_velocity, f.angular_velocity);
  if constexpr (is_exact_v<Scalar>)
    if (f.angular_velocity == Scalar(0) && !to_vec3(v.angular_velocity, Scalar(1)).isZero())
      throw Irrational("an angular velocity in deg/s (pi / 180 to rad/s)");
  b.p_CgIc_B = to_vec3(v.impulse_center, f.length);
  return b;
}

template <typename Scalar>
Scene<Scalar> to_scene(const CaseSpec& c) {
  const UnitFactors<Scalar> f = unit_factors<Scalar>(c.units);
  Scene<Scalar> s;
  for (int i = 0; i < 2; ++i) s.body[i] = to_body(c.vehicles[i], f);
  s.R_WC = contact_rotation<Scalar>(c.contact);
  s.restitution = to_scalar<Scalar>(c.restitution);
  if (const auto& e = c.energy_split) {
    const Scalar a = to_scalar<Scalar>(e->values[0]), b = to_scalar<Scalar>(e->values[1]);
    const Scalar sum = a + b;
    // E_i = F^2 / (2 k_i) for one force F: the stiffer vehicle takes the smaller share.
    if (e->rule == "stiffness") s.energy_share = std::array<Scalar, 2>{b / sum, a / sum};
    else s.energy_share = std::array<Scalar, 2>{a / sum, b / sum};
  }
  const Scalar V_rn = relative_velocity_C(s).x();
  if (!(V_rn > Scalar(0)))
    throw CaseError("$.vehicles", "not approaching: the relative normal velocity at the impulse centre is " +
                                      scalar_to_text(Scalar(V_rn / f.velocity), 6) + " " +
                                      unit_label(c.units, "velocity") +
                                      " (must be > 0; the normal points into vehicle 1)");
  return s;
}

template <typename Scalar>
std::vector<Strategy<Scalar>> to_strategies(const CaseSpec& c) {
  std::vector<Strategy<Scalar>> out;
  for (const auto& s : c.strategies) out.push_back(to_strategy<Scalar>(s));
  return out;
}

// Compiled once per scalar of the list, in case_format/src/instantiate.cpp, not in every object that
// reads a case at one of them.
#define IMPACT3D_EXTERN_TO_SCENE_(type, name, u)                 \
  extern template Scene<type> to_scene<type>(const CaseSpec&); \
  extern template std::vector<Strategy<type>> to_strategies<type>(const CaseSpec&);
IMPACT3D_SCALARS(IMPACT3D_EXTERN_TO_SCENE_)
#undef IMPACT3D_EXTERN_TO_SCENE_

}  // namespace impact3d::case_format
