// The benchmarks' naive peers (bench/naive/pc_crash.hpp: std::sin/cos, arrays, Cramer's rule; and
// bench/naive/pc_crash.py, vectorized NumPy) compute the same pc-crash impulse as impact3d from the same
// raw parameters, so that timing them side by side compares like with like. Independent of impact3d's
// code: their own rotations, K, point velocities and solves.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>

#include "naive/pc_crash.hpp"
#include "support.hpp"

using namespace impact3d;
using namespace impact3d::test;

namespace {

struct Collision {
  bench::NaiveCase raw;
  Scene<double> scene;
};

// Seeded random approaching collisions, as raw parameters and as the scene impact3d builds from them.
std::vector<Collision> collisions(std::size_t n) {
  std::mt19937_64 g(20261121);
  std::uniform_real_distribution<double> u(0, 1);
  auto in = [&](double a, double b) { return a + (b - a) * u(g); };
  std::vector<Collision> out;
  while (out.size() < n) {
    Collision k{};
    bench::NaiveCase& c = k.raw;
    Scene<double>& s = k.scene;
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
    if (relative_velocity_C(s).x() > 1.0) out.push_back(k);  // approaching, as impact3d requires
  }
  return out;
}

// A peer's impulses against impact3d's, case by case: counts and the worst relative difference.
struct Agreement {
  int compared = 0, full = 0, sliding = 0, near_threshold = 0;
  double worst = 0;
};

Agreement agree(const std::vector<Collision>& cs, const std::vector<bench::NaiveImpulse>& peer) {
  Agreement r;
  REQUIRE(peer.size() == cs.size());
  for (std::size_t k = 0; k < cs.size(); ++k) {
    const auto a = analyze(cs[k].scene, {PcCrash<double>{cs[k].raw.mu}});
    const auto& sol = a.solutions[0].impulse;
    // A mu within rounding of the GIR may fall on either side in two computations: not a comparison.
    if (std::abs(cs[k].raw.mu - *sol.gir) <= rounding::agreement_bound(a.amplification) * *sol.gir) {
      ++r.near_threshold;
      continue;
    }
    REQUIRE(peer[k].full == (sol.regime == Regime::full));
    ++(peer[k].full ? r.full : r.sliding);
    const double err = (Eigen::Vector3d(peer[k].P[0], peer[k].P[1], peer[k].P[2]) - sol.P_C).norm() / sol.P_C.norm();
    r.worst = std::max(r.worst, err);
    // Two double computations of one closed form, each within relative_bound of the exact impulse.
    CHECK(err <= rounding::agreement_bound(a.amplification));
    ++r.compared;
  }
  return r;
}

void check_agreement(const Agreement& r) {
  CHECK(r.compared + r.near_threshold == 2000);
  CHECK(r.full > 100);
  CHECK(r.sliding > 100);
  CHECK(r.near_threshold < 10);
  // The benchmarks' claim (BENCHMARKS.md): the peers agree with impact3d to 1e-12 on these cases.
  INFO("worst relative difference " << r.worst);
  CHECK(r.worst < 1e-12);
  CHECK(r.worst > 0);  // two different routes: a difference of exactly zero everywhere would mean one route
}

}  // namespace

TEST_CASE("the naive C++ pc-crash peer agrees with impact3d on seeded random collisions", "[peers]") {
  const auto cs = collisions(2000);
  std::vector<bench::NaiveImpulse> peer;
  for (const auto& k : cs) peer.push_back(bench::naive_pc_crash(k.raw));
  check_agreement(agree(cs, peer));
}

TEST_CASE("the NumPy pc-crash peer agrees with impact3d on the same collisions", "[peers]") {
  const auto cs = collisions(2000);
  const auto dir = std::filesystem::temp_directory_path() / ("impact3d-peers-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream csv(dir / "cases.csv");
    csv << std::setprecision(17);
    // The columns of pc_crash.py's COLUMNS, in its order.
    for (int i = 1; i <= 2; ++i) {
      csv << (i == 1 ? "" : ",") << "mass_" << i;
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) csv << ",J" << p << q << "_" << i;
      csv << ",yaw_" << i << ",pitch_" << i << ",roll_" << i;
      for (const char* k : {"v", "w", "r"})
        for (int p = 0; p < 3; ++p) csv << "," << k << p << "_" << i;
    }
    csv << ",normal_yaw,normal_pitch,tangent_roll,restitution,mu\n";
    for (const auto& k : cs) {
      const bench::NaiveCase& c = k.raw;
      for (int i = 0; i < 2; ++i) {
        const bench::NaiveVehicle& v = c.veh[i];
        csv << (i == 0 ? "" : ",") << v.mass;
        for (int p = 0; p < 3; ++p)
          for (int q = 0; q < 3; ++q) csv << "," << v.J[p][q];
        csv << "," << v.yaw << "," << v.pitch << "," << v.roll;
        for (const double* x : {v.v, v.w, v.r})
          for (int p = 0; p < 3; ++p) csv << "," << x[p];
      }
      csv << "," << c.normal_yaw << "," << c.normal_pitch << "," << c.tangent_roll << "," << c.restitution << "," << c.mu
          << "\n";
    }
  }
  // Fixed paths written by the test itself: no outside text reaches the shell.
  const std::string cmd = std::string("'") + IMPACT3D_PYTHON + "' '" + IMPACT3D_BENCH_DIR + "/naive/pc_crash.py' < '" +
                          (dir / "cases.csv").string() + "' > '" + (dir / "impulses.csv").string() + "'";
  REQUIRE(std::system(cmd.c_str()) == 0);
  std::ifstream in(dir / "impulses.csv");
  std::vector<bench::NaiveImpulse> peer;
  for (std::string line; std::getline(in, line);) {
    bench::NaiveImpulse n{};
    int full = 0;
    REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%d", &n.P[0], &n.P[1], &n.P[2], &full) == 4);
    n.full = full == 1;
    peer.push_back(n);
  }
  std::filesystem::remove_all(dir);
  check_agreement(agree(cs, peer));
}
