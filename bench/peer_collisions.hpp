// The collisions the peers (bench/naive/) are timed on in bench_peers.cpp and held to impact3d on in
// tests/mechanics/check_naive_peers.cpp: seeded random raw parameters, and the scene impact3d builds from them.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "impact3d/mechanics/kinematics.hpp"
#include "impact3d/mechanics/raw_collision.hpp"
#include "impact3d/mechanics/rotation.hpp"
#include "naive/pc_crash.hpp"

namespace impact3d::bench {

// The same raw parameters as impact3d's RawCollision, for the lean path and the batches.
inline RawCollision<double> raw_of(const NaiveCase& c) {
  RawCollision<double> r;
  for (int i = 0; i < 2; ++i) {
    const NaiveVehicle& v = c.veh[i];
    RawVehicle<double>& w = r.vehicle[i];
    w.mass = v.mass;
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) w.J_B(p, q) = v.J[p][q];
      w.v_W(p) = v.v[p], w.w_B(p) = v.w[p], w.p_CgIc_B(p) = v.r[p];
    }
    w.yaw_deg = v.yaw, w.pitch_deg = v.pitch, w.roll_deg = v.roll;
  }
  r.normal_yaw_deg = c.normal_yaw, r.normal_pitch_deg = c.normal_pitch, r.tangent_roll_deg = c.tangent_roll;
  r.restitution = c.restitution;
  return r;
}

// The same raw parameters in another scalar (from double: exactly).
template <typename To>
RawCollision<To> raw_as(const RawCollision<double>& r) {
  RawCollision<To> out;
  for (int i = 0; i < 2; ++i) {
    const RawVehicle<double>& v = r.vehicle[i];
    out.vehicle[i] = {To(v.mass), v.J_B.cast<To>(), To(v.yaw_deg), To(v.pitch_deg), To(v.roll_deg),
                      v.v_W.cast<To>(), v.w_B.cast<To>(), v.p_CgIc_B.cast<To>()};
  }
  out.normal_yaw_deg = To(r.normal_yaw_deg), out.normal_pitch_deg = To(r.normal_pitch_deg);
  out.tangent_roll_deg = To(r.tangent_roll_deg), out.restitution = To(r.restitution);
  return out;
}

// The scene impact3d builds from them, rotations by rotation_zyx_deg as a case file's are.
inline Scene<double> scene_of(const NaiveCase& c) {
  const RawCollision<double> r = raw_of(c);
  Scene<double> s;
  for (int i = 0; i < 2; ++i) {
    const RawVehicle<double>& v = r.vehicle[i];
    s.body[i] = {v.mass, v.J_B, rotation_zyx_deg(v.yaw_deg, v.pitch_deg, v.roll_deg), v.v_W, v.w_B, v.p_CgIc_B};
  }
  s.R_WC = rotation_zyx_deg(r.normal_yaw_deg, r.normal_pitch_deg, r.tangent_roll_deg);
  s.restitution = r.restitution;
  return s;
}

// Approaching collisions (V_rn > 1 m/s): full inertia tensors (principal moments turned by up to 15
// degrees), yawed, pitched and rolled vehicles, a tilted and rolled contact frame, eps in [0, 1] and mu in
// [0.05, 1.5], so that both pc-crash regimes occur.
inline std::vector<NaiveCase> random_collisions(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  auto in = [&](double a, double b) { return a + (b - a) * u(g); };
  std::vector<NaiveCase> out;
  while (out.size() < n) {
    NaiveCase c{};
    for (NaiveVehicle& v : c.veh) {
      v.mass = in(700, 3500);
      const double ixx = in(300, 1500), iyy = in(1200, 6000), izz = iyy + in(0.5, 1.0) * ixx;
      const double roll = in(-15, 15), pitch = in(-15, 15), yaw = in(-15, 15);  // the last first, as GCC took them
      const Mat3<double> Q = rotation_zyx_deg(yaw, pitch, roll);
      const Mat3<double> J = Q * Eigen::Vector3d(ixx, iyy, izz).asDiagonal() * Q.transpose();
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) v.J[p][q] = (J(p, q) + J(q, p)) / 2;
      v.yaw = in(-180, 180), v.pitch = in(-12, 12), v.roll = in(-12, 12);
      const double v_max[3] = {25, 25, 1}, w_max[3] = {0.3, 0.3, 1.5}, r_lo[3] = {-2.6, -1.0, -0.5}, r_hi[3] = {2.6, 1.0, 0.4};
      for (int p = 0; p < 3; ++p) v.v[p] = in(-v_max[p], v_max[p]), v.w[p] = in(-w_max[p], w_max[p]), v.r[p] = in(r_lo[p], r_hi[p]);
    }
    c.normal_yaw = in(-180, 180), c.normal_pitch = in(-25, 25), c.tangent_roll = in(-30, 30);
    c.restitution = u(g);
    c.mu = in(0.05, 1.5);
    if (relative_velocity_C(scene_of(c)).x() > 1.0) out.push_back(c);
  }
  return out;
}

}  // namespace impact3d::bench
