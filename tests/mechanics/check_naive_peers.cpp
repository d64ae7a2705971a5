// The benchmarks' naive peers (bench/naive/pc_crash.hpp: std::sin/cos, arrays, Cramer's rule; and
// bench/naive/pc_crash.py, vectorized NumPy) compute the same pc-crash impulse as impact3d from the same
// raw parameters, so that timing them side by side compares like with like. Independent of impact3d's
// code: their own rotations, K, point velocities and solves.
#include <catch2/catch.hpp>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "cli_process.hpp"
#include "impact3d/mechanics/analysis.hpp"
#include "peer_collisions.hpp"

namespace check_naive_peers {

using namespace impact3d;
using namespace impact3d::test;

namespace {

// A peer's impulses against impact3d's, case by case: counts and the worst relative difference.
struct Agreement {
  int compared = 0, full = 0, sliding = 0, near_threshold = 0;
  double worst = 0;
};

Agreement agree(const std::vector<bench::NaiveCase>& cs, const std::vector<bench::NaiveImpulse>& peer) {
  Agreement r;
  REQUIRE(peer.size() == cs.size());
  for (std::size_t k = 0; k < cs.size(); ++k) {
    const auto a = analyze(bench::scene_of(cs[k]), {PcCrash<double>{cs[k].mu}});
    const auto& sol = a.solutions[0].impulse;
    // A mu within rounding of the GIR may fall on either side in two computations: not a comparison.
    if (std::abs(cs[k].mu - *sol.gir) <= rounding::agreement_bound(a.amplification) * *sol.gir) {
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
  const auto cs = bench::random_collisions(2000, 20261121);
  std::vector<bench::NaiveImpulse> peer;
  for (const auto& c : cs) peer.push_back(bench::naive_pc_crash(c));
  check_agreement(agree(cs, peer));
}

TEST_CASE("the NumPy pc-crash peer agrees with impact3d on the same collisions", "[peers]") {
  const auto cs = bench::random_collisions(2000, 20261121);
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
    for (const bench::NaiveCase& c : cs) {
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
  // The peer's own program on the test's own file, run without a shell; it is not hostile input, so it
  // gets no address-space limit (NumPy's threads reserve much).
  const Run py = run_program(IMPACT3D_PYTHON, {IMPACT3D_BENCH_DIR "/naive/pc_crash.py"}, (dir / "cases.csv").string(), "", 120, 0);
  INFO(py.err);
  REQUIRE(py.status == 0);
  std::istringstream in(py.out);
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

}  // namespace check_naive_peers
