// pc-crash from raw parameters (angles, full tensors, velocities, impulse centres) to the impulse, side by
// side in one run: impact3d's analyze and the naive scalar peer (bench/naive/pc_crash.hpp), on the same
// seeded random approaching collisions. tests/check_naive_peers.cpp holds the peer to impact3d.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "impact3d/numeric/analysis.hpp"
#include "impact3d/numeric/rotation.hpp"
#include "naive/pc_crash.hpp"

using namespace impact3d;

namespace {

Scene<double> scene_of(const bench::NaiveCase& c) {
  Scene<double> s;
  for (int i = 0; i < 2; ++i) {
    const bench::NaiveVehicle& v = c.veh[i];
    RigidBody<double>& b = s.body[i];
    b.mass = v.mass;
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) b.J_B(p, q) = v.J[p][q];
      b.v_W[p] = v.v[p];
      b.w_B[p] = v.w[p];
      b.p_CgIc_B[p] = v.r[p];
    }
    b.R_WB = rotation_zyx_deg(v.yaw, v.pitch, v.roll);
  }
  s.R_WC = rotation_zyx_deg(c.normal_yaw, c.normal_pitch, c.tangent_roll);
  s.restitution = c.restitution;
  return s;
}

// 1024 approaching collisions, mu = 0.5 and eps = 0.1 as in the measurements.
const std::vector<bench::NaiveCase>& cases() {
  static const std::vector<bench::NaiveCase> all = [] {
    std::mt19937_64 g(11);
    std::uniform_real_distribution<double> u(0, 1);
    auto in = [&](double a, double b) { return a + (b - a) * u(g); };
    std::vector<bench::NaiveCase> out;
    while (out.size() < 1024) {
      bench::NaiveCase c{};
      for (auto& v : c.veh) {
        v.mass = in(700, 3500);
        const double ixx = in(300, 1500), iyy = in(1200, 6000), izz = iyy + in(0.5, 1.0) * ixx;
        const Mat3<double> Q = rotation_zyx_deg(in(-15, 15), in(-15, 15), in(-15, 15));
        const Mat3<double> J = Q * Eigen::Vector3d(ixx, iyy, izz).asDiagonal() * Q.transpose();
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q) v.J[p][q] = (J(p, q) + J(q, p)) / 2;
        v.yaw = in(-180, 180), v.pitch = in(-12, 12), v.roll = in(-12, 12);
        for (int p = 0; p < 3; ++p) v.v[p] = in(-25, 25), v.w[p] = in(-0.3, 0.3), v.r[p] = in(-1.5, 1.5);
      }
      c.normal_yaw = in(-180, 180), c.normal_pitch = in(-10, 10), c.tangent_roll = in(-20, 20);
      c.restitution = 0.1;
      c.mu = 0.5;
      if (relative_velocity_C(scene_of(c)).x() > 1.0) out.push_back(c);
    }
    return out;
  }();
  return all;
}

void pc_crash_naive(benchmark::State& state) {
  const auto& cs = cases();
  for (auto _ : state)
    for (const auto& c : cs) benchmark::DoNotOptimize(bench::naive_pc_crash(c));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cs.size()));
}

template <Engine E>
void pc_crash_analyze(benchmark::State& state) {
  const auto& cs = cases();
  for (auto _ : state)
    for (const auto& c : cs) benchmark::DoNotOptimize(analyze(scene_of(c), {PcCrash<double>{c.mu}}, E));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cs.size()));
}

}  // namespace

BENCHMARK(pc_crash_naive);
BENCHMARK(pc_crash_analyze<Engine::generated>);
BENCHMARK(pc_crash_analyze<Engine::direct>);
