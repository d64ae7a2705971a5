// The benchmarks' naive peer (bench/naive/pc_crash.hpp: std::sin/cos, arrays, Cramer's rule) computes the
// same pc-crash impulse as impact3d from the same raw parameters, so that timing them side by side compares
// like with like. Independent of impact3d's code: its own rotations, K, point velocities and solves.
#include <catch2/catch.hpp>

#include "naive/pc_crash.hpp"
#include "support.hpp"

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("the naive pc-crash peer agrees with impact3d on seeded random collisions", "[peers]") {
  std::mt19937_64 g(20261121);
  std::uniform_real_distribution<double> u(0, 1);
  auto in = [&](double a, double b) { return a + (b - a) * u(g); };
  int compared = 0, full = 0, sliding = 0, near_threshold = 0;
  double worst = 0;
  while (compared < 2000) {
    bench::NaiveCase c{};
    Scene<double> s;
    for (int i = 0; i < 2; ++i) {
      RigidBody<double> b = random_body(g);  // full tensors, velocities, impulse centres
      bench::NaiveVehicle& v = c.veh[i];
      v.mass = b.mass;
      for (int p = 0; p < 3; ++p) {
        for (int q = 0; q < 3; ++q) v.J[p][q] = b.J_B(p, q);
        v.v[p] = b.v_W[p];
        v.w[p] = b.w_B[p];
        v.r[p] = b.p_CgIc_B[p];
      }
      v.yaw = in(-180, 180), v.pitch = in(-12, 12), v.roll = in(-12, 12);
      b.R_WB = rotation_zyx_deg(v.yaw, v.pitch, v.roll);
      s.body[i] = b;
    }
    c.normal_yaw = in(-180, 180), c.normal_pitch = in(-25, 25), c.tangent_roll = in(-30, 30);
    s.R_WC = rotation_zyx_deg(c.normal_yaw, c.normal_pitch, c.tangent_roll);
    c.restitution = s.restitution = u(g);
    c.mu = in(0.05, 1.5);
    if (!(relative_velocity_C(s).x() > 1.0)) continue;  // approaching, as impact3d requires
    const auto a = analyze(s, {PcCrash<double>{c.mu}});
    const auto& sol = a.solutions[0].impulse;
    // A mu within rounding of the GIR may fall on either side in two computations: not a comparison.
    if (std::abs(c.mu - *sol.gir) <= rounding::agreement_bound(a.amplification) * *sol.gir) {
      ++near_threshold;
      continue;
    }
    const bench::NaiveImpulse n = bench::naive_pc_crash(c);
    REQUIRE(n.full == (sol.regime == Regime::full));
    ++(n.full ? full : sliding);
    const double err = (Eigen::Vector3d(n.P[0], n.P[1], n.P[2]) - sol.P_C).norm() / sol.P_C.norm();
    worst = std::max(worst, err);
    // Two double computations of one closed form, each within relative_bound of the exact impulse.
    CHECK(err <= rounding::agreement_bound(a.amplification));
    ++compared;
  }
  CHECK(compared == 2000);
  CHECK(full > 100);
  CHECK(sliding > 100);
  CHECK(near_threshold < 10);
  // The benchmarks' claim (BENCHMARKS.md): the peer agrees with impact3d to 1e-12 on these cases.
  INFO("worst relative difference " << worst);
  CHECK(worst < 1e-12);
  CHECK(worst > 0);  // two different routes: a difference of exactly zero everywhere would mean one route
}
