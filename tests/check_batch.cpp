// The SIMD batches (numeric/batch/columns.hpp) against the scalar lean path, row by row, on seeded random
// raw collisions (bench/peer_collisions.hpp, both regimes) mixed with rows the lanes must not decide:
// separating, mu exactly at the GIR, an undefined phi_FI plane, an overflowing mass, a NaN input.
//
// Rows decided on the lanes differ from solve_lean only by roundings of the kind the rounding model
// counts: the vectorized sine and cosine (measured below against the scalar ones, in ulps), fused
// multiply-adds and the lanes' hypot, each a relative error of an ulp or two in an input or an
// operation. Both computations are then within rounding::relative_bound (kResultRoundings eps A) of the
// exact impulse of the same rows, so within agreement_bound (2 kResultRoundings eps A) of each other,
// A the case's amplification (rounding.hpp). Everything decided is equal: status, regime, warning codes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "impact3d/numeric/batch/columns.hpp"
#include "impact3d/numeric/lean.hpp"
#include "peer_collisions.hpp"

using namespace impact3d;

namespace {

// Distance in units in the last place, through the ordered integer representation.
double ulps(double a, double b) {
  if (a == b) return 0;
  auto key = [](double x) {
    std::int64_t i;
    std::memcpy(&i, &x, sizeof i);
    return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;
  };
  return std::abs(static_cast<double>(key(a) - key(b)));
}

}  // namespace

// The widest instruction set again when a test case ends, whatever it chose.
struct WidestAfter {
  ~WidestAfter() { batch::use_simd(batch::simd_available().at(0)); }
};

// Every instruction set this CPU runs, one after the other (the widest is what users get).
#define FOR_EACH_SIMD()                                                   \
  const WidestAfter restore;                                              \
  const std::string simd = GENERATE(from_range(batch::simd_available())); \
  REQUIRE(batch::use_simd(simd));                                         \
  INFO("instruction set " << simd);

TEST_CASE("the lanes' sine and cosine of degrees are within 4 ulps of the scalar path's", "[batch]") {
  FOR_EACH_SIMD();
  // Both reduce by quarter turns to [-45, 45] degrees. The scalar path takes radians as (rest pi) / 180,
  // two roundings, the lanes as rest (pi / 180), one rounding of a rounded constant: the radians differ
  // by up to 2 ulps, which sine near 0 keeps. glibc documents its sin and cos within an ulp; xsimd's are
  // Cephes-style polynomials on [-pi/4, pi/4] with no stated bound, so this measurement is what holds
  // them to an ulp: 4 ulps in all. Multiples of 90 degrees are exact on both.
  std::mt19937_64 g(3);
  std::uniform_real_distribution<double> u(-720, 720);
  std::vector<double> deg;
  for (int k = -8; k <= 8; ++k) deg.push_back(45.0 * k);
  for (double x : {1e-300, -1e-300, 1e-10, 89.999999999, 0.5, -0.0}) deg.push_back(x);
  while (deg.size() < 100003) deg.push_back(u(g));
  std::vector<double> s(deg.size()), c(deg.size());
  batch::sin_cos_deg_columns(deg.data(), s.data(), c.data(), deg.size());
  double worst = 0;
  std::size_t exact_quarters = 0;
  for (std::size_t i = 0; i < deg.size(); ++i) {
    const SinCos<double> r = sin_cos_deg(deg[i]);
    worst = std::max({worst, ulps(s[i], r.s), ulps(c[i], r.c)});
    if (std::fmod(deg[i], 90.0) == 0) {
      exact_quarters += s[i] == r.s && c[i] == r.c;
      CHECK(std::abs(s[i]) + std::abs(c[i]) == 1);
    }
  }
  INFO(batch::simd_name() << ": worst " << worst << " ulps over " << deg.size() << " angles");
  CHECK(worst <= 4);
  CHECK(exact_quarters == 10);  // -360, -270, ..., 360 from the grid of 45s, and -0
}

TEST_CASE("the SIMD batch gives solve_lean's status, regime and warnings on every row, and its impulse within "
          "agreement_bound",
          "[batch]") {
  FOR_EACH_SIMD();
  auto cs = bench::random_collisions(4000, 29);
  std::vector<RawCollision<double>> rows;
  std::vector<double> mus;
  for (const auto& c : cs) rows.push_back(bench::raw_of(c)), mus.push_back(c.mu);
  // Rows the lanes must leave to the scalar path, spread over lane positions.
  const std::size_t n_random = rows.size();
  for (std::size_t k = 0; k < 40; ++k) {
    RawCollision<double> r = rows[k];
    double mu = mus[k];
    switch (k % 5) {
      case 0:  // separating
        for (auto& v : r.vehicle) v.v_W = -v.v_W, v.w_B = -v.w_B;
        break;
      case 1: {  // mu exactly at the GIR: undecided
        const Scene<double> s = scene_of(r);
        mu = *solve_lean(s, Strategy<double>(PcCrash<double>{0})).impulse.gir;
        break;
      }
      case 2:  // head-on along the normal: phi_FI undefined
        for (int i = 0; i < 2; ++i) {
          auto& v = r.vehicle[i];
          v.J_B = Mat3<double>(Vec3<double>(500, 2500, 2800).asDiagonal());
          v.yaw_deg = v.pitch_deg = v.roll_deg = 0;
          v.v_W = Vec3<double>(i == 0 ? 10 : -10, 0, 0), v.w_B.setZero(), v.p_CgIc_B = Vec3<double>(i == 0 ? 2 : -2, 0, 0);
        }
        r.normal_yaw_deg = 180, r.normal_pitch_deg = 0, r.tangent_roll_deg = 0;
        break;
      case 3:  // overflowing masses: a singular system
        r.vehicle[0].mass = r.vehicle[1].mass = 1e300;
        break;
      case 4:  // a NaN product of inertia: K is NaN, every closed form too
        r.vehicle[1].J_B(0, 1) = std::numeric_limits<double>::quiet_NaN();
        break;
    }
    rows.insert(rows.begin() + static_cast<std::ptrdiff_t>(97 * k + k % 7), r);
    mus.insert(mus.begin() + static_cast<std::ptrdiff_t>(97 * k + k % 7), mu);
  }
  rows.resize(rows.size() - 3);  // a tail shorter than any lane group
  mus.resize(rows.size());
  batch::CollisionTable table(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) table.set(i, rows[i], mus[i]);
  batch::ImpulseTable out(rows.size());
  const batch::CollisionColumns in = table.columns();
  // Two ranges, as two threads would split it.
  const std::size_t on_scalar = batch::pc_crash_columns(in, out.columns(), 0, rows.size() / 2 + 1) +
                                batch::pc_crash_columns(in, out.columns(), rows.size() / 2 + 1, rows.size());

  int solved = 0, full = 0, sliding = 0, statuses[3] = {0, 0, 0}, undecided = 0, undefined = 0;
  double worst = 0;  // |dP| / (eps A |P|)
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const RawCollision<double> back = batch::row_of(in, i);
    CHECK(back.vehicle[1].J_B(2, 1) == rows[i].vehicle[1].J_B(2, 1));
    const Scene<double> s = scene_of(rows[i]);
    const auto r = solve_lean(s, Strategy<double>(PcCrash<double>{mus[i]}));
    INFO("row " << i);
    REQUIRE(out.status[i] == static_cast<std::uint8_t>(r.status));
    ++statuses[out.status[i]];
    CHECK(out.warnings[i] == r.warnings);
    undecided += has_warning(r.warnings, WarningCode::undecided);
    undefined += has_warning(r.warnings, WarningCode::plane_undefined);
    if (r.status != Status::solved) {
      CHECK(std::isnan(out.P_C[0][i]));
      continue;
    }
    ++solved;
    CHECK(out.regime[i] == static_cast<std::uint8_t>(r.impulse.regime));
    ++(r.impulse.regime == Regime::full ? full : sliding);
    const Vec3<double> P(out.P_C[0][i], out.P_C[1][i], out.P_C[2][i]);
    const double A = make_problem<GeneratedEngine>(s).amplification;
    const double err = (P - r.impulse.P_C).norm() / r.impulse.P_C.norm();
    CHECK(err <= rounding::agreement_bound(A));
    worst = std::max(worst, err / (std::numeric_limits<double>::epsilon() * A));
  }
  INFO(batch::simd_name() << ": worst " << worst << " eps A over " << solved << " rows");
  CHECK(rows.size() == n_random + 40 - 3);
  CHECK(statuses[0] == solved);
  CHECK(statuses[1] == 8);  // the separating rows
  CHECK(statuses[2] == 16);  // the overflowing and the NaN rows
  CHECK(statuses[0] + statuses[1] + statuses[2] == static_cast<int>(rows.size()));
  CHECK(undecided >= 8);
  CHECK(undefined >= 8);
  CHECK(full > 500);
  CHECK(sliding > 500);
  // The lanes decided every row but the 40 built for the scalar path (each fails a lane's test: not
  // approaching, not finite, a plane or a regime within twice the cheap bound), the two ranges' tails
  // (under a lane group each) and the few random rows whose decisions fall within twice the cheap bound.
  INFO(on_scalar << " rows on the scalar path");
  CHECK(on_scalar >= 40);
  CHECK(on_scalar <= 40 + 2 * 8 + 20);
  CHECK(worst <= 2 * rounding::kResultRoundings);
}
